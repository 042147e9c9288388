/* Loader.h: the textures' loader, included by jello.cpp as "textures\loader.h" (Windows). */
#ifndef TEXTURE_LOADER_H
#define TEXTURE_LOADER_H
int loadTextures(void);
#endif
