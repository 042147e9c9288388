/* openGL-headers.h: the GL headers of each platform, as the course starter has them. */
#ifndef _OPENGL_HEADERS_H_
#define _OPENGL_HEADERS_H_

#if defined(WIN32) || defined(_WIN32)
  #include <windows.h>
  #include <GL/gl.h>
  #include <GL/glu.h>
  #include <GL/glut.h>
#elif defined(__APPLE__)
  #include <OpenGL/gl.h>
  #include <OpenGL/glu.h>
  #include <GLUT/glut.h>
#else
  #include <GL/gl.h>
  #include <GL/glu.h>
  #include <GL/glut.h>
#endif

#endif
