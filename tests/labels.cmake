# The suite's labels, read by CTest after the tests are listed (TEST_INCLUDE_FILES):
#   long:        5 s or more of a release build's test run (2026-11-28, this project's 2-core
#                machine): `make test` runs them, `make test-quick` leaves them out.
#   sanitizers:  20 s or more under AddressSanitizer and UBSan, whose code shorter tests take
#                through the sanitizers too: `make test-sanitize` leaves them out (it keeps the
#                kernels' range and thread tests and the contacts, where an index goes wrong).
# The window's tests (tests/CMakeLists.txt) are labelled where they are added. A parameterised
# test's name is GoogleTest's with its parameter: "NAME  # GetParam() = VALUE" (ctest -N).
# One line a test: its labels, a bar, its name.
set(jello_labelled
  "long sanitizers|GraderPrograms.BuildsAndGradesEveryStudentShapedProgramAsItsExpectationSays"
  "long sanitizers|Grader.PassesTheCorrectSolutionAndGivesEveryMutantExactlyItsDiagnosisInWords"
  "long sanitizers|Grader.AgreesWithTheCorrectSolutionWithinEachWorldsOwnTolerance"
  "long sanitizers|Grader.AClassGradedInThreePartsAndMergedIsTheOneRunsReport"
  "long|Grader.ContainsHostileSubmissionsAndHarmsNothingElse"
  "long|GraderPrograms.ALibraryCopyOfAnySizeCrowdsOutNoneOfTheCoursesFiles"
  "long sanitizers|GraderIntegrity.PrintingReadingTheEnvironmentAndFillingDisksChangeNoGrade"
  "long|GraderIntegrity.AnswersThatCompareAsAnythingFail"
  "long sanitizers|Report.RecommendsOnlyStepsThatCheckCallsStable"
  "long sanitizers|Report.AWorldsOwnSettingInASweepIsThatRowAndTheReferenceIsBelowEverySweep"
  "long sanitizers|Report.ASceneKeepsItsRecommendedSettingInItsOwnKeys"
  "long sanitizers|Report.CsvPlotSummaryAndRecommendations"
  "long sanitizers|Report/RecommendedCommands.RunAsPrintedAndReproduceTheReportedError/\"RK4\""
  "long sanitizers|Report/RecommendedCommands.RunAsPrintedAndReproduceTheReportedError/\"RK45\""
  "long sanitizers|ReportOrders.AFitFarFromItsTheoryIsPutDownToTheContactsOfTheRun"
  "long sanitizers|ReportProgress.CountsToItsTotalNeverPastItAndEndsItsLineBeforeTheSummary"
  "long sanitizers|Signals.AReportStoppedWhileGnuplotDrawsLeavesNoTemporaryPicture"
  "long sanitizers|Signals.AFrameBeingWrittenLeavesNoTemporaryFileBehind"
  "long|SpecialFiles.AFifoWriterThatStallsIsRefusedAfterFiveSecondsAndASlowOneIsRead"
  "long|SpecialFiles.AFifoIsReadAndAFifoWithoutWriterDoesNotHang"
  "long sanitizers|FullDisk.AReportWhosePictureDoesNotFitNamesNoPictureAndLeavesNoEmptyFile"
  "long sanitizers|Cli.InATerminalTheProgressLineEndsWithItsFinalStateAndANewlineBeforeTheSummary"
  "long sanitizers|Conservation.SymplecticSchemesKeepTheEnergyOfAnUndampedCubeForTenSeconds"
  "long sanitizers|Conservation.UndampedSpringsKeepRk4EnergyOverOneSecond"
  "long sanitizers|SceneBodies.ABarHeldAtOneEndCarriesItsWeightOnThePinsAndSagsAsOneOverK"
  "long sanitizers|RandomKernels.SpecialisedAgreesWithGeneralOverAThousandSteps"
  "long sanitizers|Friction.ABlockOnASlopeStaysBelowTheFrictionAngleAndSlidesAboveIt"
  "long sanitizers|FrictionState.TheJellyOnTheSlopeSticksWithEnoughFrictionAndSlidesWithout"
  "long sanitizers|Pins.EveryIntegratorKeepsItsOrderOnAScenWithPins"
  "long sanitizers|Obstacles.AJellyDroppedOnASphereEndsRestingOnItCentred"
  "sanitizers|Grader.TakesEachWorldsToleranceFromItsOwnSensitivity"
  "sanitizers|HostileNames.AWorldNamedLikeGnuplotCodeIsDrawnAsItsNameAndRunsNothing"
  "sanitizers|Cli.ThreadsAreAWholeNumberAndChangeNoResult"
  "sanitizers|Cli.StaticFindsTheCantileverAtRestAndCompareMaterialsTablesTheFourRuns"
  "sanitizers|CheckCommand.TextJsonAndMap"
  "sanitizers|SceneBodies.EveryIntegratorKeepsItsOrderOnAPinnedSphereJelly"
  "sanitizers|SceneDrawing.TheFrictionColouringShowsStickingGreenAndSlidingOrange"
  "sanitizers|SceneFile.ACourseWorldThroughASceneIsTheCourseWorldBitForBit"
  "sanitizers|Pins.TheStabilityAnalysisSeesOnlyTheFreeCoordinates"
  "sanitizers|Rk45.MeetsItsToleranceWithinAFactorOfTen"
  "sanitizers|ShowcaseWorlds.RunOrStopCleanly"
  "sanitizers|StepVerdict.IsChecksVerdictAndLimitAndBoundsALargeBody"
  "sanitizers|Implicit.StableAtTenTimesRk4sLargestStableStepOnAStiffWorld"
  "sanitizers|Implicit.EachStepSolvesBackwardEulerToItsTolerance"
  "sanitizers|SmallAndWildStates.AVelocityOf1e100IsADivergenceNotAnEigensolverFailure"
  "sanitizers|Elements.ACantileverSagsAsBeamTheorySaysAndConvergesAsTheMeshRefines"
  "sanitizers|Stability.AnUndampedCubeStartingDeformedIsNeverCalledStableNearItsLimit"
  "sanitizers|Worlds/Prediction.WithinThreeQuartersAndElevenTenthsOfTheObservedLimit/stiff_2e4_w  # GetParam() = world/stress/stiff-2e4.w"
  "sanitizers|Integrators/ConvergenceOrder.MatchesTheory/EULER  # GetParam() = EULER"
  "sanitizers|Integrators/ConvergenceOrder.MatchesTheory/SYMPLECTIC  # GetParam() = SYMPLECTIC"
  "sanitizers|Integrators/ConvergenceOrder.MatchesTheory/MIDPOINT  # GetParam() = MIDPOINT"
  "sanitizers|Integrators/ConvergenceOrder.MatchesTheory/VERLET  # GetParam() = VERLET"
  "sanitizers|Integrators/ConvergenceOrder.MatchesTheory/RK4  # GetParam() = RK4"
  "sanitizers|Integrators/ConvergenceOrder.MatchesTheory/IMPLICIT  # GetParam() = IMPLICIT")
# set_tests_properties, as CTest reads this file (set_property(TEST) is not there), sets a test's
# labels whole: all of them at once.
foreach(jello_entry IN LISTS jello_labelled)
  string(FIND "${jello_entry}" "|" jello_bar)
  string(SUBSTRING "${jello_entry}" 0 ${jello_bar} jello_labels)
  math(EXPR jello_bar "${jello_bar} + 1")
  string(SUBSTRING "${jello_entry}" ${jello_bar} -1 jello_name)
  string(REPLACE " " ";" jello_labels "${jello_labels}")
  set_tests_properties("${jello_name}" PROPERTIES LABELS "${jello_labels}")
endforeach()
