// coursefiles.h: the course API's files, built into the grader (from grader/course/): what is
// built with a student's code never depends on where ./grade is run from. (The course worlds of
// the agreement check are read from world/, beside ./grade or in the sources.)
#pragma once

namespace jello::grader {
extern const char* const kCourseJelloH;    // grader/course/jello.h
extern const char* const kCoursePhysicsH;  // grader/course/physics.h
extern const char* const kProbeSource;     // grader/course/probe.cpp
}  // namespace jello::grader
