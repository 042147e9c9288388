/* stdafx.h: the grader's empty stand-in for Visual Studio's precompiled header. */
#pragma message("jello-grader stand-in: <stdafx.h>")
