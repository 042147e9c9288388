/* input.cpp: the mouse, the keys, world files and screenshots, in the course starter's shape. */
#include "jello.h"
#include "input.h"

void saveScreenshot(int windowWidth, int windowHeight, char *filename)
{
  if (filename == NULL)
    return;
  Pic *in = pic_alloc(windowWidth, windowHeight, 3, NULL);
  for (int i = windowHeight - 1; i >= 0; i--)
    glReadPixels(0, windowHeight - i - 1, windowWidth, 1, GL_RGB, GL_UNSIGNED_BYTE,
                 &in->pix[i * in->nx * in->bpp]);
  if (jpeg_write(filename, in))
    printf("File saved Successfully\n");
  else
    printf("Error in Saving\n");
  pic_free(in);
}

void mouseMotionDrag(int x, int y)
{
  int vMouseDelta[2] = {x - g_vMousePos[0], y - g_vMousePos[1]};
  if (g_iRightMouseButton)
  {
    Phi += vMouseDelta[0] * 0.01;
    Theta += vMouseDelta[1] * 0.01;
    if (Phi > 2 * pi) Phi -= 2 * pi;
    if (Phi < 0) Phi += 2 * pi;
    if (Theta > pi / 2 - 0.01) Theta = pi / 2 - 0.01;
    if (Theta < -pi / 2 + 0.01) Theta = -pi / 2 + 0.01;
  }
  if (g_iMiddleMouseButton)
  {
    R += vMouseDelta[1] * 0.01;
    if (R < 0.2) R = 0.2;
  }
  g_vMousePos[0] = x;
  g_vMousePos[1] = y;
}

void mouseMotion(int x, int y)
{
  g_vMousePos[0] = x;
  g_vMousePos[1] = y;
}

void mouseButton(int button, int state, int x, int y)
{
  switch (button)
  {
    case GLUT_LEFT_BUTTON: g_iLeftMouseButton = (state == GLUT_DOWN); break;
    case GLUT_MIDDLE_BUTTON: g_iMiddleMouseButton = (state == GLUT_DOWN); break;
    case GLUT_RIGHT_BUTTON: g_iRightMouseButton = (state == GLUT_DOWN); break;
  }
  g_vMousePos[0] = x;
  g_vMousePos[1] = y;
}

void keyboardFunc(unsigned char key, int x, int y)
{
  switch (key)
  {
    case 27: exit(0); break;
    case 'e': Theta = pi / 6; Phi = pi / 6; R = 6; break;
    case 'v': viewingMode = 1 - viewingMode; break;
    case 'h': shear = 1 - shear; break;
    case 's': structural = 1 - structural; break;
    case 'b': bend = 1 - bend; break;
    case 'p': pause = 1 - pause; break;
    case 'z': R -= 0.2; if (R < 0.2) R = 0.2; break;
    case 'x': R += 0.2; break;
    case ' ': saveScreenToFile = 1 - saveScreenToFile; break;
  }
}

void readWorld(char * fileName, struct world * jello)
{
  FILE * file = fopen(fileName, "r");
  if (file == NULL)
  {
    printf("can't open file\n");
    exit(1);
  }
  fscanf(file, "%s\n", jello->integrator);
  fscanf(file, "%lf %d\n", &jello->dt, &jello->n);
  fscanf(file, "%lf %lf %lf %lf\n", &jello->kElastic, &jello->dElastic, &jello->kCollision,
         &jello->dCollision);
  fscanf(file, "%lf\n", &jello->mass);
  fscanf(file, "%d\n", &jello->incPlanePresent);
  if (jello->incPlanePresent == 1)
    fscanf(file, "%lf %lf %lf %lf\n", &jello->a, &jello->b, &jello->c, &jello->d);
  fscanf(file, "%d\n", &jello->resolution);
  jello->forceField = (struct point *)malloc(jello->resolution * jello->resolution *
                                              jello->resolution * sizeof(struct point));
  for (int i = 0; i <= jello->resolution - 1; i++)
    for (int j = 0; j <= jello->resolution - 1; j++)
      for (int k = 0; k <= jello->resolution - 1; k++)
        fscanf(file, "%lf %lf %lf\n",
               &jello->forceField[i * jello->resolution * jello->resolution + j * jello->resolution + k].x,
               &jello->forceField[i * jello->resolution * jello->resolution + j * jello->resolution + k].y,
               &jello->forceField[i * jello->resolution * jello->resolution + j * jello->resolution + k].z);
  for (int i = 0; i <= 7; i++)
    for (int j = 0; j <= 7; j++)
      for (int k = 0; k <= 7; k++)
        fscanf(file, "%lf %lf %lf\n", &jello->p[i][j][k].x, &jello->p[i][j][k].y, &jello->p[i][j][k].z);
  for (int i = 0; i <= 7; i++)
    for (int j = 0; j <= 7; j++)
      for (int k = 0; k <= 7; k++)
        fscanf(file, "%lf %lf %lf\n", &jello->v[i][j][k].x, &jello->v[i][j][k].y, &jello->v[i][j][k].z);
  fclose(file);
}

void writeWorld(char * fileName, struct world * jello)
{
  FILE * file = fopen(fileName, "w");
  if (file == NULL)
  {
    printf("can't open file\n");
    exit(1);
  }
  fprintf(file, "%s\n", jello->integrator);
  fprintf(file, "%lf %d\n", jello->dt, jello->n);
  fprintf(file, "%lf %lf %lf %lf\n", jello->kElastic, jello->dElastic, jello->kCollision, jello->dCollision);
  fprintf(file, "%lf\n", jello->mass);
  fprintf(file, "%d\n", jello->incPlanePresent);
  if (jello->incPlanePresent == 1)
    fprintf(file, "%lf %lf %lf %lf\n", jello->a, jello->b, jello->c, jello->d);
  fprintf(file, "%d\n", jello->resolution);
  fclose(file);
}
