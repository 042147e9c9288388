// graderfiles.h: the files the grader builds with a student's code, built into the grader from
// grader/course/ (the course API's headers, the probe) and grader/standins/ (GL, GLU, GLUT and
// the pic library that draw nothing; the Windows headers and the standard includes of a lenient
// build): what is built with a student's code never depends on where ./grade is run from. (The
// course worlds of the agreement check are read from world/, beside ./grade or in the sources.)
#pragma once

#include <string>
#include <vector>

namespace jello::grader {

struct GraderFile {
  const char* path;  // under grader/, e.g. "course/jello.h", "standins/always/GL/glut.h"
  const char* text;
};
// Every file of grader/course/ and grader/standins/, sorted by path (made by CMake).
const std::vector<GraderFile>& graderFiles();
// The text of the file at `path` (under grader/); throws std::logic_error when there is none.
std::string graderFile(const std::string& path);

}  // namespace jello::grader
