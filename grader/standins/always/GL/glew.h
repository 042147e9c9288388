/* GL/glew.h: the grader's stand-in, which draws nothing (jello-grader-gl.h). */
#ifndef JELLO_GRADER_GLEW_H
#define JELLO_GRADER_GLEW_H
#include <jello-grader-gl.h>
#define GLEW_OK 0
#define glewInit(...) (GLEW_OK)
#define glewIsSupported(...) (0)
#define glewGetErrorString(...) ("")
#define glewExperimental jello_grader_glew_experimental
static unsigned char jello_grader_glew_experimental;
#endif
