/* conio.h: the grader's stand-in for the Windows console header (a leniency the report names):
   no key is ever pressed. */
#pragma message("jello-grader stand-in: <conio.h>")
#ifndef JELLO_GRADER_CONIO_H
#define JELLO_GRADER_CONIO_H
static inline int _kbhit(void) { return 0; }
static inline int _getch(void) { return 0; }
static inline int getch(void) { return 0; }
static inline int kbhit(void) { return 0; }
#endif
