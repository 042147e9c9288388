#include "performanceCounter.h"

static double now()
{
  struct timeval t;
  gettimeofday(&t, 0);
  return t.tv_sec + 1e-6 * t.tv_usec;
}

void PerformanceCounter::StartCounter() { startTime = now(); }
void PerformanceCounter::StopCounter() { stopTime = now(); }
double PerformanceCounter::GetElapsedTime() { return stopTime - startTime; }
