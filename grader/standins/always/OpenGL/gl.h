/* OpenGL/gl.h: the grader's stand-in, which draws nothing (jello-grader-gl.h). */
#include <jello-grader-gl.h>
