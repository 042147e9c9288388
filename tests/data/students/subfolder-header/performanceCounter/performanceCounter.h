/* performanceCounter.h: a frame timer kept in a subfolder, as some course starters have it. */
#ifndef _PERFORMANCECOUNTER_H_
#define _PERFORMANCECOUNTER_H_

#include <sys/time.h>

class PerformanceCounter
{
public:
  void StartCounter();
  void StopCounter();
  double GetElapsedTime();

private:
  double startTime = 0, stopTime = 0;
};

#endif
