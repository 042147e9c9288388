/* pic.cpp: the picture library's source, shipped with the program (a fixture of the grader's
   tests): pictures in memory, written as PPM. */
#include <stdio.h>
#include <string.h>
#include "pic.h"

Pic *pic_alloc(int nx, int ny, int bytes_per_pixel, Pic *opic)
{
  Pic *p = opic;
  if (!p)
    ALLOC(p, Pic, 1);
  p->nx = nx;
  p->ny = ny;
  p->bpp = bytes_per_pixel;
  ALLOC(p->pix, Pixel1, nx * ny * bytes_per_pixel);
  return p;
}

void pic_free(Pic *p)
{
  free(p->pix);
  free(p);
}

int jpeg_write(char *file, Pic *pic)
{
  FILE *out = fopen(file, "wb");
  if (!out)
    return FALSE;
  fprintf(out, "P6\n%d %d\n255\n", pic->nx, pic->ny);
  fwrite(pic->pix, 1, (size_t)(pic->nx * pic->ny * pic->bpp), out);
  fclose(out);
  return TRUE;
}

int ppm_get_size(char *file, int *nx, int *ny)
{
  FILE *in = fopen(file, "rb");
  if (!in)
    return FALSE;
  int ok = fscanf(in, "P6 %d %d", nx, ny) == 2;
  fclose(in);
  return ok ? TRUE : FALSE;
}

Pic_file_format pic_file_type(char *file)
{
  const char *dot = strrchr(file, '.');
  return dot && strcmp(dot, ".ppm") == 0 ? PIC_PPM_FILE : PIC_UNKNOWN_FILE;
}
