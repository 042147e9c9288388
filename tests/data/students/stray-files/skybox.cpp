/* skybox.cpp: textures for a sky around the box, an extra the student never finished wiring
   in: nothing of the program calls it. */
#include "jello.h"

unsigned int skyTextures[6];

void loadSkybox(char * files[6])
{
  glGenTextures(6, skyTextures);
  for (int face = 0; face < 6; face++)
  {
    Pic * picture = jpeg_read(files[face], NULL);
    if (picture == NULL)
      continue;
    glBindTexture(GL_TEXTURE_2D, skyTextures[face]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, picture->nx, picture->ny, 0, GL_RGB, GL_UNSIGNED_BYTE,
                 picture->pix);
    pic_free(picture);
  }
}
