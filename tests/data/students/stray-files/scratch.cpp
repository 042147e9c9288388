/* scratch.cpp: half-written notes that never compiled. */
int unfinished(int x)
{
  return x +
}
