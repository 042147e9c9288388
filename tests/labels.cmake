# The suite's labels, read by CTest after the tests are listed (TEST_INCLUDE_FILES):
#   long:        5 s or more of a release build's test run (2026-11-28, this project's 2-core
#                machine): `make test` runs them, `make test-quick` leaves them out.
#   sanitizers:  20 s or more under AddressSanitizer and UBSan, whose code shorter tests take
#                through the sanitizers too: `make test-sanitize` leaves them out (it keeps the
#                kernels' range and thread tests and the contacts, where an index goes wrong).
# The window's tests (tests/CMakeLists.txt) are labelled where they are added. A parameterised
# test's name is GoogleTest's with its parameter: "NAME  # GetParam() = VALUE" (ctest -N).
cmake_policy(VERSION 3.25)  # IN_LIST: CTest reads this file under the old policies
set(jello_long_tests
  GraderPrograms.BuildsAndGradesEveryStudentShapedProgramAsItsExpectationSays
  Grader.PassesTheCorrectSolutionAndGivesEveryMutantExactlyItsDiagnosisInWords
  Grader.AgreesWithTheCorrectSolutionWithinEachWorldsOwnTolerance
  Grader.AClassGradedInThreePartsAndMergedIsTheOneRunsReport
  Grader.ContainsHostileSubmissionsAndHarmsNothingElse
  GraderPrograms.ALibraryCopyOfAnySizeCrowdsOutNoneOfTheCoursesFiles
  GraderIntegrity.PrintingReadingTheEnvironmentAndFillingDisksChangeNoGrade
  GraderIntegrity.AnswersThatCompareAsAnythingFail
  Report.RecommendsOnlyStepsThatCheckCallsStable
  Report.AWorldsOwnSettingInASweepIsThatRowAndTheReferenceIsBelowEverySweep
  Report.ASceneKeepsItsRecommendedSettingInItsOwnKeys
  Report.CsvPlotSummaryAndRecommendations
  "Report/RecommendedCommands.RunAsPrintedAndReproduceTheReportedError/\"RK4\""
  "Report/RecommendedCommands.RunAsPrintedAndReproduceTheReportedError/\"RK45\""
  ReportOrders.AFitFarFromItsTheoryIsPutDownToTheContactsOfTheRun
  ReportProgress.CountsToItsTotalNeverPastItAndEndsItsLineBeforeTheSummary
  Signals.AReportStoppedWhileGnuplotDrawsLeavesNoTemporaryPicture
  Signals.AFrameBeingWrittenLeavesNoTemporaryFileBehind
  SpecialFiles.AFifoWriterThatStallsIsRefusedAfterFiveSecondsAndASlowOneIsRead
  SpecialFiles.AFifoIsReadAndAFifoWithoutWriterDoesNotHang
  FullDisk.AReportWhosePictureDoesNotFitNamesNoPictureAndLeavesNoEmptyFile
  Cli.InATerminalTheProgressLineEndsWithItsFinalStateAndANewlineBeforeTheSummary
  Conservation.SymplecticSchemesKeepTheEnergyOfAnUndampedCubeForTenSeconds
  Conservation.UndampedSpringsKeepRk4EnergyOverOneSecond
  SceneBodies.ABarHeldAtOneEndCarriesItsWeightOnThePinsAndSagsAsOneOverK
  RandomKernels.SpecialisedAgreesWithGeneralOverAThousandSteps
  Friction.ABlockOnASlopeStaysBelowTheFrictionAngleAndSlidesAboveIt
  FrictionState.TheJellyOnTheSlopeSticksWithEnoughFrictionAndSlidesWithout
  Pins.EveryIntegratorKeepsItsOrderOnAScenWithPins
  Obstacles.AJellyDroppedOnASphereEndsRestingOnItCentred)
set(jello_sanitizer_slow_tests
  GraderPrograms.BuildsAndGradesEveryStudentShapedProgramAsItsExpectationSays
  Grader.PassesTheCorrectSolutionAndGivesEveryMutantExactlyItsDiagnosisInWords
  Grader.AgreesWithTheCorrectSolutionWithinEachWorldsOwnTolerance
  Grader.AClassGradedInThreePartsAndMergedIsTheOneRunsReport
  Grader.TakesEachWorldsToleranceFromItsOwnSensitivity
  GraderIntegrity.PrintingReadingTheEnvironmentAndFillingDisksChangeNoGrade
  Report.RecommendsOnlyStepsThatCheckCallsStable
  Report.AWorldsOwnSettingInASweepIsThatRowAndTheReferenceIsBelowEverySweep
  Report.ASceneKeepsItsRecommendedSettingInItsOwnKeys
  Report.CsvPlotSummaryAndRecommendations
  "Report/RecommendedCommands.RunAsPrintedAndReproduceTheReportedError/\"RK4\""
  "Report/RecommendedCommands.RunAsPrintedAndReproduceTheReportedError/\"RK45\""
  ReportOrders.AFitFarFromItsTheoryIsPutDownToTheContactsOfTheRun
  ReportProgress.CountsToItsTotalNeverPastItAndEndsItsLineBeforeTheSummary
  Signals.AReportStoppedWhileGnuplotDrawsLeavesNoTemporaryPicture
  Signals.AFrameBeingWrittenLeavesNoTemporaryFileBehind
  FullDisk.AReportWhosePictureDoesNotFitNamesNoPictureAndLeavesNoEmptyFile
  HostileNames.AWorldNamedLikeGnuplotCodeIsDrawnAsItsNameAndRunsNothing
  Cli.InATerminalTheProgressLineEndsWithItsFinalStateAndANewlineBeforeTheSummary
  Cli.ThreadsAreAWholeNumberAndChangeNoResult
  Cli.StaticFindsTheCantileverAtRestAndCompareMaterialsTablesTheFourRuns
  CheckCommand.TextJsonAndMap
  Conservation.SymplecticSchemesKeepTheEnergyOfAnUndampedCubeForTenSeconds
  Conservation.UndampedSpringsKeepRk4EnergyOverOneSecond
  SceneBodies.ABarHeldAtOneEndCarriesItsWeightOnThePinsAndSagsAsOneOverK
  SceneBodies.EveryIntegratorKeepsItsOrderOnAPinnedSphereJelly
  SceneDrawing.TheFrictionColouringShowsStickingGreenAndSlidingOrange
  SceneFile.ACourseWorldThroughASceneIsTheCourseWorldBitForBit
  RandomKernels.SpecialisedAgreesWithGeneralOverAThousandSteps
  Friction.ABlockOnASlopeStaysBelowTheFrictionAngleAndSlidesAboveIt
  FrictionState.TheJellyOnTheSlopeSticksWithEnoughFrictionAndSlidesWithout
  Pins.EveryIntegratorKeepsItsOrderOnAScenWithPins
  Pins.TheStabilityAnalysisSeesOnlyTheFreeCoordinates
  Obstacles.AJellyDroppedOnASphereEndsRestingOnItCentred
  Rk45.MeetsItsToleranceWithinAFactorOfTen
  ShowcaseWorlds.RunOrStopCleanly
  StepVerdict.IsChecksVerdictAndLimitAndBoundsALargeBody
  Implicit.StableAtTenTimesRk4sLargestStableStepOnAStiffWorld
  Implicit.EachStepSolvesBackwardEulerToItsTolerance
  SmallAndWildStates.AVelocityOf1e100IsADivergenceNotAnEigensolverFailure
  Elements.ACantileverSagsAsBeamTheorySaysAndConvergesAsTheMeshRefines
  Stability.AnUndampedCubeStartingDeformedIsNeverCalledStableNearItsLimit
  "Worlds/Prediction.WithinThreeQuartersAndElevenTenthsOfTheObservedLimit/stiff_2e4_w  # GetParam() = world/stress/stiff-2e4.w"
  "Integrators/ConvergenceOrder.MatchesTheory/EULER  # GetParam() = EULER"
  "Integrators/ConvergenceOrder.MatchesTheory/SYMPLECTIC  # GetParam() = SYMPLECTIC"
  "Integrators/ConvergenceOrder.MatchesTheory/MIDPOINT  # GetParam() = MIDPOINT"
  "Integrators/ConvergenceOrder.MatchesTheory/VERLET  # GetParam() = VERLET"
  "Integrators/ConvergenceOrder.MatchesTheory/RK4  # GetParam() = RK4"
  "Integrators/ConvergenceOrder.MatchesTheory/IMPLICIT  # GetParam() = IMPLICIT")
# set_tests_properties, as CTest reads this file (set_property(TEST) is not there), sets a test's
# labels whole: each gets both of its labels at once.
set(jello_labelled ${jello_long_tests} ${jello_sanitizer_slow_tests})
list(REMOVE_DUPLICATES jello_labelled)
foreach(jello_name IN LISTS jello_labelled)
  set(jello_labels "")
  if("${jello_name}" IN_LIST jello_long_tests)
    list(APPEND jello_labels long)
  endif()
  if("${jello_name}" IN_LIST jello_sanitizer_slow_tests)
    list(APPEND jello_labels sanitizers)
  endif()
  set_tests_properties("${jello_name}" PROPERTIES LABELS "${jello_labels}")
endforeach()
