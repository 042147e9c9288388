/* jello.cpp: the viewer's main, in the course starter's shape: it reads the world named on
   the command line, builds this student's spring list, opens the window and runs GLUT. */
#include "jello.h"
#include "showCube.h"
#include "input.h"
#include "physics.h"

double Theta = pi / 6;
double Phi = pi / 6;
double R = 6;
int g_iMenuId;
int g_vMousePos[2] = {0, 0};
int g_iLeftMouseButton = 0;
int g_iMiddleMouseButton = 0;
int g_iRightMouseButton = 0;
int shear = 0, bend = 0, structural = 1, pause = 0, viewingMode = 0, saveScreenToFile = 0;
struct world jello;
int windowWidth, windowHeight;
int sprite = 0;
std::vector<Spring> springs;

/* Every pair of points joined by a structural, shear or bend spring, once. */
void buildSprings()
{
  static const int offsets[16][3] = {{1, 0, 0},  {0, 1, 0},   {0, 0, 1},  {1, 1, 0},
                                     {1, -1, 0}, {1, 0, 1},   {1, 0, -1}, {0, 1, 1},
                                     {0, 1, -1}, {1, 1, 1},   {1, 1, -1}, {1, -1, 1},
                                     {1, -1, -1}, {2, 0, 0},  {0, 2, 0},  {0, 0, 2}};
  springs.clear();
  for (int i = 0; i <= 7; i++)
    for (int j = 0; j <= 7; j++)
      for (int k = 0; k <= 7; k++)
        for (int s = 0; s < 16; s++)
        {
          int i2 = i + offsets[s][0], j2 = j + offsets[s][1], k2 = k + offsets[s][2];
          if (i2 < 0 || i2 > 7 || j2 < 0 || j2 > 7 || k2 < 0 || k2 > 7)
            continue;
          Spring sp = {i, j, k, i2, j2, k2,
                       sqrt((double)(offsets[s][0] * offsets[s][0] + offsets[s][1] * offsets[s][1] +
                                     offsets[s][2] * offsets[s][2])) / 7.0};
          springs.push_back(sp);
        }
}

void myinit()
{
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(90.0, 1.0, 0.01, 1000.0);
  glClearColor(0.0, 0.0, 0.0, 0.0);
  glCullFace(GL_BACK);
  glEnable(GL_CULL_FACE);
  glShadeModel(GL_SMOOTH);
  glEnable(GL_POLYGON_SMOOTH);
  glEnable(GL_LINE_SMOOTH);
}

void reshape(int w, int h)
{
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(60.0f, 1.0 * w / (h > 0 ? h : 1), 0.01, 1000.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  windowWidth = w;
  windowHeight = h;
  glutPostRedisplay();
}

void display()
{
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(R * cos(Phi) * cos(Theta), R * sin(Phi) * cos(Theta), R * sin(Theta),
            0.0, 0.0, 0.0, 0.0, 0.0, 1.0);
  GLfloat lightPosition[] = {-1.999f, -1.999f, -1.999f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  glEnable(GL_LIGHTING);
  showCube(&jello);
  glDisable(GL_LIGHTING);
  showBoundingBox();
  glutSwapBuffers();
}

void doIdle()
{
  char s[20] = "picxxxx.ppm";
  if (saveScreenToFile == 1)
  {
    sprintf(s, "%04d.ppm", sprite);
    saveScreenshot(windowWidth, windowHeight, s);
    sprite++;
  }
  if (sprite >= 300)
    exit(0);
  if (pause == 0)
  {
    for (int step = 0; step < jello.n; step++)
    {
      if (strcmp(jello.integrator, "RK4") == 0)
        RK4(&jello);
      else
        Euler(&jello);
    }
  }
  glutPostRedisplay();
}

int main(int argc, char ** argv)
{
  if (argc < 2)
  {
    printf("Oops! You didn't say the jello world file!\n");
    printf("Usage: %s [worldfile]\n", argv[0]);
    exit(0);
  }
  readWorld(argv[1], &jello);
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGBA | GLUT_DEPTH);
  windowWidth = 640;
  windowHeight = 480;
  glutInitWindowSize(windowWidth, windowHeight);
  glutInitWindowPosition(0, 0);
  glutCreateWindow("Jello cube");
  glutDisplayFunc(display);
  glutIdleFunc(doIdle);
  glutMotionFunc(mouseMotionDrag);
  glutReshapeFunc(reshape);
  glutPassiveMotionFunc(mouseMotion);
  glutMouseFunc(mouseButton);
  glutKeyboardFunc(keyboardFunc);
  buildSprings();
  myinit();
  glutMainLoop();
  return 0;
}
