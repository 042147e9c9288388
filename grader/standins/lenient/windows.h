/* windows.h: the grader's stand-in for the Windows header, for programs written on Windows
   (a leniency the report names). It holds the types and the timing and sleeping calls that
   course programs use; nothing of it draws or waits. */
#pragma message("jello-grader stand-in: <windows.h>")
#ifndef JELLO_GRADER_WINDOWS_H
#define JELLO_GRADER_WINDOWS_H

#include <stdint.h>
#include <time.h>

typedef int BOOL;
typedef unsigned char BYTE;
typedef unsigned short WORD;
typedef unsigned int DWORD;
typedef unsigned int UINT;
typedef long LONG;
typedef long long LONGLONG;
typedef void* HANDLE;
typedef void* HWND;
typedef void* HDC;
typedef void* HGLRC;
typedef void* HINSTANCE;
typedef const char* LPCSTR;
typedef char* LPSTR;
typedef union {
  struct {
    DWORD LowPart;
    LONG HighPart;
  } u;
  LONGLONG QuadPart;
} LARGE_INTEGER;
#ifndef TRUE
#define TRUE 1
#endif
#ifndef FALSE
#define FALSE 0
#endif
#define WINAPI
#define APIENTRY
#define CALLBACK
#define WINGDIAPI
#define __stdcall
#define __cdecl

static inline BOOL QueryPerformanceFrequency(LARGE_INTEGER* frequency) {
  frequency->QuadPart = 1000000000LL;
  return TRUE;
}
static inline BOOL QueryPerformanceCounter(LARGE_INTEGER* count) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  count->QuadPart = (LONGLONG)t.tv_sec * 1000000000LL + t.tv_nsec;
  return TRUE;
}
static inline DWORD GetTickCount(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (DWORD)(t.tv_sec * 1000 + t.tv_nsec / 1000000);
}
static inline void Sleep(DWORD milliseconds) { (void)milliseconds; }

#endif
