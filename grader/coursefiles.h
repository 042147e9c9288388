// coursefiles.h: the course API's files, built into the grader (from grader/course/), so that a
// copied ./grade needs nothing beside it.
#pragma once

namespace jello::grader {
extern const char* const kCourseJelloH;    // grader/course/jello.h
extern const char* const kCoursePhysicsH;  // grader/course/physics.h
extern const char* const kProbeSource;     // grader/course/probe.cpp
}  // namespace jello::grader
