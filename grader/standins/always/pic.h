/* pic.h: the grader's stand-in for the course's picture library (pic.h, libpicio). Pictures
   are made in memory as the library makes them, and never written: the grader draws nothing. */
#ifndef JELLO_GRADER_PIC_H
#define JELLO_GRADER_PIC_H

#include <stdlib.h>
#include <string.h>

typedef unsigned char Pixel1;
typedef struct {
  Pixel1 r, g, b;
} Pixel1_rgb;
typedef struct {
  Pixel1 r, g, b, a;
} Pixel1_rgba;
typedef struct {
  int nx, ny; /* width and height */
  int bpp;    /* bytes per pixel */
  Pixel1* pix;
} Pic;

#define PIC_PIXEL(pic, x, y, c) ((pic)->pix[((y) * (pic)->nx + (x)) * (pic)->bpp + (c)])
#define PIC_UNDEFINED 0
#define PIC_TIFF_FILE 1
#define PIC_PPM_FILE 2
#define PIC_JPEG_FILE 3

static inline Pic* pic_alloc(int nx, int ny, int bytes_per_pixel, Pic* opic) {
  Pic* p = opic ? opic : (Pic*)malloc(sizeof(Pic));
  if (!p) return NULL;
  p->nx = nx;
  p->ny = ny;
  p->bpp = bytes_per_pixel;
  p->pix = (Pixel1*)calloc((size_t)(nx > 0 ? nx : 1) * (size_t)(ny > 0 ? ny : 1),
                           (size_t)(bytes_per_pixel > 0 ? bytes_per_pixel : 1));
  return p;
}
static inline void pic_free(Pic* p) {
  if (p) free(p->pix);
  free(p);
}
/* Writing succeeds and writes nothing; reading finds no picture. */
static inline int jpeg_write(const char* file, Pic* pic) { return file && pic ? 1 : 0; }
static inline int ppm_write(const char* file, Pic* pic) { return file && pic ? 1 : 0; }
static inline int tiff_write(const char* file, Pic* pic) { return file && pic ? 1 : 0; }
static inline int pic_write(const char* file, Pic* pic, int type) {
  return file && pic && type >= 0 ? 1 : 0;
}
static inline Pic* jpeg_read(const char* file, Pic* opic) {
  (void)file;
  (void)opic;
  return (Pic*)0;
}
static inline Pic* ppm_read(const char* file, Pic* opic) { return jpeg_read(file, opic); }
static inline Pic* tiff_read(const char* file, Pic* opic) { return jpeg_read(file, opic); }
static inline Pic* pic_read(const char* file, Pic* opic) { return jpeg_read(file, opic); }
static inline int pic_get_size(const char* file, int* nx, int* ny) {
  (void)file;
  (void)nx;
  (void)ny;
  return 0;
}
static inline int pic_file_type(const char* file) {
  (void)file;
  return PIC_UNDEFINED;
}

#endif
