/* jello-grader-gl.h: GL, GLU and GLUT that draw nothing, for grading a student's program
   headless (docs/grading.md, "How a submission is built"). Made by scripts/make-gl-standins from
   the names and constants of the system's headers: each function is a macro that evaluates none
   of its arguments, a no-op for a void function and 0 for any other; glutMainLoop() hands the
   program to the grader, which then calls computeAcceleration, Euler and RK4. */
#ifndef JELLO_GRADER_GL_H
#define JELLO_GRADER_GL_H

typedef unsigned int GLenum;
typedef unsigned char GLboolean;
typedef unsigned int GLbitfield;
typedef void GLvoid;
typedef signed char GLbyte;
typedef short GLshort;
typedef int GLint;
typedef unsigned char GLubyte;
typedef unsigned short GLushort;
typedef unsigned int GLuint;
typedef int GLsizei;
typedef float GLfloat;
typedef float GLclampf;
typedef double GLdouble;
typedef double GLclampd;
typedef char GLchar;
typedef long GLintptr;
typedef long GLsizeiptr;
typedef long GLintptrARB;
typedef long GLsizeiptrARB;
typedef char GLcharARB;
typedef unsigned int GLhandleARB;
typedef unsigned short GLhalf;
typedef unsigned short GLhalfARB;
typedef unsigned short GLhalfNV;
typedef int GLfixed;
typedef long long GLint64;
typedef unsigned long long GLuint64;
typedef long long GLint64EXT;
typedef unsigned long long GLuint64EXT;
typedef struct __GLsync* GLsync;
typedef void (*GLDEBUGPROC)(GLenum, GLenum, GLuint, GLenum, GLsizei, const GLchar*, const void*);
typedef GLDEBUGPROC GLDEBUGPROCARB;
typedef struct GLUnurbs GLUnurbs;
typedef struct GLUquadric GLUquadric;
typedef struct GLUtesselator GLUtesselator;
typedef GLUnurbs GLUnurbsObj;
typedef GLUquadric GLUquadricObj;
typedef GLUtesselator GLUtesselatorObj;
typedef GLUtesselator GLUtriangulatorObj;
#ifndef APIENTRY
#define APIENTRY
#endif
#define GLAPIENTRY
#ifndef APIENTRYP
#define APIENTRYP APIENTRY*
#endif
#define GLUTCALLBACK
#define CALLBACK
/* A pointer to a GL function, as a program that loads one by hand declares it. */
#ifdef __cplusplus
#define JELLO_GRADER_PROC(name) void (*name)(...)
#else
#define JELLO_GRADER_PROC(name) void (*name)()
#endif

#ifdef __cplusplus
extern "C" {
#endif
/* The grader's probe: serves the grader's requests on the program's own globals, then exits. */
void jello_grader_main_loop(void);
/* glutGet: GLUT_ELAPSED_TIME the milliseconds since the program started, as GLUT counts them;
   window sizes as a 640x480 window; 0 for anything else. */
int jello_grader_glut_get(int what);
#ifdef __cplusplus
}
#endif

#define GLUT_STROKE_ROMAN ((void*)1)
#define GLUT_STROKE_MONO_ROMAN ((void*)2)
#define GLUT_BITMAP_9_BY_15 ((void*)3)
#define GLUT_BITMAP_8_BY_13 ((void*)4)
#define GLUT_BITMAP_TIMES_ROMAN_10 ((void*)5)
#define GLUT_BITMAP_TIMES_ROMAN_24 ((void*)6)
#define GLUT_BITMAP_HELVETICA_10 ((void*)7)
#define GLUT_BITMAP_HELVETICA_12 ((void*)8)
#define GLUT_BITMAP_HELVETICA_18 ((void*)9)
#define GLUT_ACCUM 0x0004
#define GLUT_ACTION_CONTINUE_EXECUTION 2
#define GLUT_ACTION_EXIT 0
#define GLUT_ACTION_GLUTMAINLOOP_RETURNS 1
#define GLUT_ACTION_ON_WINDOW_CLOSE 0x01F9
#define GLUT_ACTIVE_ALT 0x0004
#define GLUT_ACTIVE_CTRL 0x0002
#define GLUT_ACTIVE_SHIFT 0x0001
#define GLUT_ACTIVE_SUPER 0x0008
#define GLUT_ALLOW_DIRECT_CONTEXT 1
#define GLUT_ALLOW_NEGATIVE_WINDOW_POSITION 0x0207
#define GLUT_ALPHA 0x0008
#define GLUT_API_VERSION 4
#define GLUT_APPSTATUS_PAUSE 0x0001
#define GLUT_APPSTATUS_RESUME 0x0002
#define GLUT_AUX 0x1000
#define GLUT_AUX1 0x1000
#define GLUT_AUX2 0x2000
#define GLUT_AUX3 0x4000
#define GLUT_AUX4 0x8000
#define GLUT_BLUE 0x0002
#define GLUT_BORDERLESS 0x0800
#define GLUT_CAPTIONLESS 0x0400
#define GLUT_COMPATIBILITY_PROFILE 0x0002
#define GLUT_CORE_PROFILE 0x0001
#define GLUT_CREATE_NEW_CONTEXT 0
#define GLUT_CURSOR_BOTTOM_LEFT_CORNER 0x0013
#define GLUT_CURSOR_BOTTOM_RIGHT_CORNER 0x0012
#define GLUT_CURSOR_BOTTOM_SIDE 0x000D
#define GLUT_CURSOR_CROSSHAIR 0x0009
#define GLUT_CURSOR_CYCLE 0x0005
#define GLUT_CURSOR_DESTROY 0x0003
#define GLUT_CURSOR_FULL_CROSSHAIR 0x0066
#define GLUT_CURSOR_HELP 0x0004
#define GLUT_CURSOR_INFO 0x0002
#define GLUT_CURSOR_INHERIT 0x0064
#define GLUT_CURSOR_LEFT_ARROW 0x0001
#define GLUT_CURSOR_LEFT_RIGHT 0x000B
#define GLUT_CURSOR_LEFT_SIDE 0x000E
#define GLUT_CURSOR_NONE 0x0065
#define GLUT_CURSOR_RIGHT_ARROW 0x0000
#define GLUT_CURSOR_RIGHT_SIDE 0x000F
#define GLUT_CURSOR_SPRAY 0x0006
#define GLUT_CURSOR_TEXT 0x0008
#define GLUT_CURSOR_TOP_LEFT_CORNER 0x0010
#define GLUT_CURSOR_TOP_RIGHT_CORNER 0x0011
#define GLUT_CURSOR_TOP_SIDE 0x000C
#define GLUT_CURSOR_UP_DOWN 0x000A
#define GLUT_CURSOR_WAIT 0x0007
#define GLUT_DEBUG 0x0001
#define GLUT_DEPTH 0x0010
#define GLUT_DEVICE_IGNORE_KEY_REPEAT 0x0262
#define GLUT_DEVICE_KEY_REPEAT 0x0263
#define GLUT_DIRECT_RENDERING 0x01FE
#define GLUT_DISPLAY_MODE_POSSIBLE 0x0190
#define GLUT_DOUBLE 0x0002
#define GLUT_DOWN 0x0000
#define GLUT_ELAPSED_TIME 0x02BC
#define GLUT_ENTERED 0x0001
#define GLUT_FORCE_DIRECT_CONTEXT 3
#define GLUT_FORCE_INDIRECT_CONTEXT 0
#define GLUT_FORWARD_COMPATIBLE 0x0002
#define GLUT_FULLY_COVERED 0x0003
#define GLUT_FULLY_RETAINED 0x0001
#define GLUT_FULL_SCREEN 0x01FF
#define GLUT_GAME_MODE_ACTIVE 0x0000
#define GLUT_GAME_MODE_DISPLAY_CHANGED 0x0006
#define GLUT_GAME_MODE_HEIGHT 0x0003
#define GLUT_GAME_MODE_PIXEL_DEPTH 0x0004
#define GLUT_GAME_MODE_POSSIBLE 0x0001
#define GLUT_GAME_MODE_REFRESH_RATE 0x0005
#define GLUT_GAME_MODE_WIDTH 0x0002
#define GLUT_GEOMETRY_VISUALIZE_NORMALS 0x0205
#define GLUT_GREEN 0x0001
#define GLUT_HAS_DIAL_AND_BUTTON_BOX 0x025B
#define GLUT_HAS_JOYSTICK 0x0264
#define GLUT_HAS_KEYBOARD 0x0258
#define GLUT_HAS_MOUSE 0x0259
#define GLUT_HAS_MULTI 1
#define GLUT_HAS_OVERLAY 0x0322
#define GLUT_HAS_SPACEBALL 0x025A
#define GLUT_HAS_TABLET 0x025C
#define GLUT_HIDDEN 0x0000
#define GLUT_INDEX 0x0001
#define GLUT_INIT_DISPLAY_MODE 0x01F8
#define GLUT_INIT_FLAGS 0x0202
#define GLUT_INIT_MAJOR_VERSION 0x0200
#define GLUT_INIT_MINOR_VERSION 0x0201
#define GLUT_INIT_PROFILE 0x0203
#define GLUT_INIT_STATE 0x007C
#define GLUT_INIT_WINDOW_HEIGHT 0x01F7
#define GLUT_INIT_WINDOW_WIDTH 0x01F6
#define GLUT_INIT_WINDOW_X 0x01F4
#define GLUT_INIT_WINDOW_Y 0x01F5
#define GLUT_JOYSTICK_AXES 0x0267
#define GLUT_JOYSTICK_BUTTONS 0x0266
#define GLUT_JOYSTICK_BUTTON_A 0x0001
#define GLUT_JOYSTICK_BUTTON_B 0x0002
#define GLUT_JOYSTICK_BUTTON_C 0x0004
#define GLUT_JOYSTICK_BUTTON_D 0x0008
#define GLUT_JOYSTICK_POLL_RATE 0x0268
#define GLUT_KEY_ALT_L 0x0074
#define GLUT_KEY_ALT_R 0x0075
#define GLUT_KEY_BEGIN 0x006E
#define GLUT_KEY_CTRL_L 0x0072
#define GLUT_KEY_CTRL_R 0x0073
#define GLUT_KEY_DELETE 0x006F
#define GLUT_KEY_DOWN 0x0067
#define GLUT_KEY_END 0x006B
#define GLUT_KEY_F1 0x0001
#define GLUT_KEY_F10 0x000A
#define GLUT_KEY_F11 0x000B
#define GLUT_KEY_F12 0x000C
#define GLUT_KEY_F2 0x0002
#define GLUT_KEY_F3 0x0003
#define GLUT_KEY_F4 0x0004
#define GLUT_KEY_F5 0x0005
#define GLUT_KEY_F6 0x0006
#define GLUT_KEY_F7 0x0007
#define GLUT_KEY_F8 0x0008
#define GLUT_KEY_F9 0x0009
#define GLUT_KEY_HOME 0x006A
#define GLUT_KEY_INSERT 0x006C
#define GLUT_KEY_LEFT 0x0064
#define GLUT_KEY_NUM_LOCK 0x006D
#define GLUT_KEY_PAGE_DOWN 0x0069
#define GLUT_KEY_PAGE_UP 0x0068
#define GLUT_KEY_REPEAT_DEFAULT 0x0002
#define GLUT_KEY_REPEAT_OFF 0x0000
#define GLUT_KEY_REPEAT_ON 0x0001
#define GLUT_KEY_RIGHT 0x0066
#define GLUT_KEY_SHIFT_L 0x0070
#define GLUT_KEY_SHIFT_R 0x0071
#define GLUT_KEY_SUPER_L 0x0076
#define GLUT_KEY_SUPER_R 0x0077
#define GLUT_KEY_UP 0x0065
#define GLUT_LAYER_IN_USE 0x0321
#define GLUT_LEFT 0x0000
#define GLUT_LEFT_BUTTON 0x0000
#define GLUT_LUMINANCE 0x0200
#define GLUT_MENU_IN_USE 0x0001
#define GLUT_MENU_NOT_IN_USE 0x0000
#define GLUT_MENU_NUM_ITEMS 0x012C
#define GLUT_MIDDLE_BUTTON 0x0001
#define GLUT_MULTISAMPLE 0x0080
#define GLUT_NORMAL 0x0000
#define GLUT_NORMAL_DAMAGED 0x0324
#define GLUT_NOT_VISIBLE 0x0000
#define GLUT_NUM_BUTTON_BOX_BUTTONS 0x025F
#define GLUT_NUM_DIALS 0x0260
#define GLUT_NUM_MOUSE_BUTTONS 0x025D
#define GLUT_NUM_SPACEBALL_BUTTONS 0x025E
#define GLUT_NUM_TABLET_BUTTONS 0x0261
#define GLUT_OVERLAY 0x0001
#define GLUT_OVERLAY_DAMAGED 0x0325
#define GLUT_OVERLAY_POSSIBLE 0x0320
#define GLUT_OWNS_JOYSTICK 0x0265
#define GLUT_PARTIALLY_RETAINED 0x0002
#define GLUT_RED 0x0000
#define GLUT_RENDERING_CONTEXT 0x01FD
#define GLUT_RGB 0x0000
#define GLUT_RGBA 0x0000
#define GLUT_RIGHT_BUTTON 0x0002
#define GLUT_SCREEN_HEIGHT 0x00C9
#define GLUT_SCREEN_HEIGHT_MM 0x00CB
#define GLUT_SCREEN_WIDTH 0x00C8
#define GLUT_SCREEN_WIDTH_MM 0x00CA
#define GLUT_SINGLE 0x0000
#define GLUT_SKIP_STALE_MOTION_EVENTS 0x0204
#define GLUT_SPACEBALL_BUTTON_A 0x0001
#define GLUT_SPACEBALL_BUTTON_B 0x0002
#define GLUT_SPACEBALL_BUTTON_C 0x0004
#define GLUT_SPACEBALL_BUTTON_D 0x0008
#define GLUT_SPACEBALL_BUTTON_E 0x0010
#define GLUT_SRGB 0x1000
#define GLUT_STENCIL 0x0020
#define GLUT_STEREO 0x0100
#define GLUT_STROKE_FONT_DRAW_JOIN_DOTS 0x0206
#define GLUT_TRANSPARENT_INDEX 0x0323
#define GLUT_TRY_DIRECT_CONTEXT 2
#define GLUT_UP 0x0001
#define GLUT_USE_CURRENT_CONTEXT 1
#define GLUT_VERSION 0x01FC
#define GLUT_VIDEO_RESIZE_HEIGHT 0x038D
#define GLUT_VIDEO_RESIZE_HEIGHT_DELTA 0x0389
#define GLUT_VIDEO_RESIZE_IN_USE 0x0385
#define GLUT_VIDEO_RESIZE_POSSIBLE 0x0384
#define GLUT_VIDEO_RESIZE_WIDTH 0x038C
#define GLUT_VIDEO_RESIZE_WIDTH_DELTA 0x0388
#define GLUT_VIDEO_RESIZE_X 0x038A
#define GLUT_VIDEO_RESIZE_X_DELTA 0x0386
#define GLUT_VIDEO_RESIZE_Y 0x038B
#define GLUT_VIDEO_RESIZE_Y_DELTA 0x0387
#define GLUT_VISIBLE 0x0001
#define GLUT_WINDOW_ACCUM_ALPHA_SIZE 0x0072
#define GLUT_WINDOW_ACCUM_BLUE_SIZE 0x0071
#define GLUT_WINDOW_ACCUM_GREEN_SIZE 0x0070
#define GLUT_WINDOW_ACCUM_RED_SIZE 0x006F
#define GLUT_WINDOW_ALPHA_SIZE 0x006E
#define GLUT_WINDOW_BLUE_SIZE 0x006D
#define GLUT_WINDOW_BORDER_HEIGHT 0x01FB
#define GLUT_WINDOW_BORDER_WIDTH 0x01FA
#define GLUT_WINDOW_BUFFER_SIZE 0x0068
#define GLUT_WINDOW_COLORMAP_SIZE 0x0077
#define GLUT_WINDOW_CURSOR 0x007A
#define GLUT_WINDOW_DEPTH_SIZE 0x006A
#define GLUT_WINDOW_DOUBLEBUFFER 0x0073
#define GLUT_WINDOW_FORMAT_ID 0x007B
#define GLUT_WINDOW_GREEN_SIZE 0x006C
#define GLUT_WINDOW_HEADER_HEIGHT 0x01FB
#define GLUT_WINDOW_HEIGHT 0x0067
#define GLUT_WINDOW_NUM_CHILDREN 0x0076
#define GLUT_WINDOW_NUM_SAMPLES 0x0078
#define GLUT_WINDOW_PARENT 0x0075
#define GLUT_WINDOW_RED_SIZE 0x006B
#define GLUT_WINDOW_RGBA 0x0074
#define GLUT_WINDOW_SRGB 0x007D
#define GLUT_WINDOW_STENCIL_SIZE 0x0069
#define GLUT_WINDOW_STEREO 0x0079
#define GLUT_WINDOW_WIDTH 0x0066
#define GLUT_WINDOW_X 0x0064
#define GLUT_WINDOW_Y 0x0065
#define GLUT_XLIB_IMPLEMENTATION 13
#include <jello-grader-gl-constants-1.h>
#include <jello-grader-gl-constants-2.h>
#include <jello-grader-gl-constants-3.h>
#include <jello-grader-gl-constants-4.h>
#include <jello-grader-gl-functions-1.h>
#include <jello-grader-gl-functions-2.h>
#include <jello-grader-gl-functions-3.h>
#include <jello-grader-gl-functions-4.h>
#include <jello-grader-gl-functions-5.h>
#include <jello-grader-gl-functions-6.h>

#endif
