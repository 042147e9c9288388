/* pic.h: the picture library's header as the course ships it with its source (pic.cpp beside
   it): its macros, its file kinds, its PPM size reader. Written for the grader's tests. */
#ifndef PIC_LIBRARY_H
#define PIC_LIBRARY_H

#include <stdlib.h>

#define ALLOC(ptr, type, n)                                  \
  {                                                          \
    ptr = (type *)malloc((unsigned)((n) * sizeof(type)));    \
    if (!ptr) {                                              \
      fprintf(stderr, "pic: no memory for %d bytes\n", (int)((n) * sizeof(type))); \
      exit(1);                                               \
    }                                                        \
  }
#define TRUE 1
#define FALSE 0

typedef unsigned char Pixel1;
typedef struct {
  int nx, ny;
  int bpp;
  Pixel1 *pix;
} Pic;
typedef enum { PIC_TIFF_FILE, PIC_PPM_FILE, PIC_JPEG_FILE, PIC_UNKNOWN_FILE } Pic_file_format;

Pic *pic_alloc(int nx, int ny, int bytes_per_pixel, Pic *opic);
void pic_free(Pic *p);
int jpeg_write(char *file, Pic *pic);
int ppm_get_size(char *file, int *nx, int *ny);
Pic_file_format pic_file_type(char *file);

#endif
