/* pic.h: the picture library's header as a student ships it (its library, with its JPEG
   writer, is not part of the submission). */
#ifndef PIC_HDR
#define PIC_HDR

typedef unsigned char Pixel1;
typedef struct {
  int nx, ny;
  int bpp;
  Pixel1 *pix;
} Pic;

Pic *pic_alloc(int nx, int ny, int bytes_per_pixel, Pic *opic);
void pic_free(Pic *p);
int jpeg_write(char *file, Pic *pic);

#endif
