/* probe.cpp: the grader's side of a submission's program, built with the student's code and run
   in the sandbox (docs/grading.md, "How a submission is built").

   Two builds. With the student's whole program (JELLO_GRADER_PROGRAM), the student's own main()
   runs first, as it would in a window: it reads the world file the grader names in argv[1] and
   does its own setup (spring lists, plane normals, ...); its call of glutMainLoop(), which the
   grader's GLUT stand-in turns into jello_grader_main_loop(), hands the program to the probe.
   With physics.cpp alone, the probe's own main() serves.

   The grader's requests arrive on file descriptor 3 and the answers leave on descriptor 4, never
   on the student's standard input or output (a printf in a global constructor or left from
   debugging goes to the log, not into the answers). The grader sends the next request only
   after the answer to this one, so no request can be read ahead. Numbers in "%.17g" (they read
   back exactly); each answer ends with a line ".". The probe speaks first, "jello-probe" (it is
   ready: the student's setup is done):
     W <world file text>   the world, in the course's .w format (readWorld's order)
     S <1024 lines x y z>  the state: 512 positions, then 512 velocities, lattice order
     A                     answers the 512 accelerations computeAcceleration gives at the state
     E N / R N             N steps of Euler / RK4; answers "ok"
     P                     answers the 512 positions and the 512 velocities
     T N                   N steps of RK4; answers the microseconds a step took
   Before its first answer the probe takes one RK4 and one Euler step and puts the world back as
   it was, so that a program that builds its lists on the first step has them. Exit status 3: a
   request it could not read. It includes no <unistd.h>: the course's jello.h declares a global
   `int pause`, which would clash with pause(2). */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <time.h>

#include "jello.h"
#include "physics.h"

/* The course's jello.cpp defines the world; physics.cpp alone may not. */
__attribute__((weak)) struct world jello;

static FILE* requests; /* the grader's descriptor 3, moved (prepare) */
static FILE* answers;  /* the grader's descriptor 4, moved */
static int requestFd = 3, answerFd = 4;

/* Declared here, not through <unistd.h> and <fcntl.h>: see above (pause). */
extern "C" int close(int);
extern "C" int fcntl(int, int, ...);
extern "C" int getpid(void);
static double programStart = -1; /* seconds, set as the program starts (prepare) */

/* The files beside the student's source (/work/files, read-only) copied into the working
   directory (/tmp), folders kept, before the program starts: its project's folder, writable. */
static void copyFiles(const char* from, const char* to) {
  DIR* folder = opendir(from);
  if (!folder) return;
  while (struct dirent* entry = readdir(folder)) {
    if (entry->d_name[0] == '.' &&
        (entry->d_name[1] == 0 || (entry->d_name[1] == '.' && entry->d_name[2] == 0)))
      continue;
    char source[4096], target[4096];
    snprintf(source, sizeof source, "%s/%s", from, entry->d_name);
    snprintf(target, sizeof target, "%s/%s", to, entry->d_name);
    struct stat info;
    if (lstat(source, &info) != 0) continue;
    if (S_ISDIR(info.st_mode)) {
      mkdir(target, 0755);
      copyFiles(source, target);
    } else if (S_ISREG(info.st_mode)) {
      FILE* in = fopen(source, "rb");
      FILE* out = in ? fopen(target, "wb") : NULL;
      char buffer[1 << 15];
      for (size_t n; out && (n = fread(buffer, 1, sizeof buffer, in)) > 0;)
        fwrite(buffer, 1, n, out);
      if (in) fclose(in);
      if (out) fclose(out);
    }
  }
  closedir(folder);
}

/* Before any constructor of the student's: the grader's channel leaves descriptors 3 and 4 for
   two of a number drawn at start, so that no fixed descriptor tells a program it is graded; the
   program's own files are laid out where it starts (copyFiles). */
__attribute__((constructor(101))) static void prepare(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  programStart = (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
  /* From 200 to 900, or below the descriptors' limit where that is lower. */
  struct rlimit open;
  unsigned low = 200, span = 700;
  if (getrlimit(RLIMIT_NOFILE, &open) == 0 && open.rlim_cur < 912) {
    low = open.rlim_cur > 300 ? 200 : 10;
    span = open.rlim_cur > low + 12 ? (unsigned)open.rlim_cur - low - 12 : 1;
  }
  int base = (int)low + (int)(((unsigned)t.tv_nsec ^ (unsigned)getpid() * 2654435761u) % span);
  int r = fcntl(3, 1030 /* F_DUPFD_CLOEXEC */, base);
  int a = fcntl(4, 1030 /* F_DUPFD_CLOEXEC */, base + 1);
  if (r < 0 || a < 0) exit(4);
  close(3);
  close(4);
  requestFd = r;
  answerFd = a;
  copyFiles("/work/files", ".");
}

/* glutGet of the GLUT stand-in (jello-grader-gl.h): the milliseconds since the program started
   for GLUT_ELAPSED_TIME, a 640x480 window for its sizes, 0 for anything else. */
extern "C" int jello_grader_glut_get(int what) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  double now = (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
  double start = programStart < 0 ? now : programStart;
  switch (what) {
    case 0x02BC: /* GLUT_ELAPSED_TIME */
      return (int)(1000 * (now - start));
    case 0x0066: /* GLUT_WINDOW_WIDTH */
    case 0x00C8: /* GLUT_SCREEN_WIDTH */
      return 640;
    case 0x0067: /* GLUT_WINDOW_HEIGHT */
    case 0x00C9: /* GLUT_SCREEN_HEIGHT */
      return 480;
    default:
      return 0;
  }
}

static void refuse(const char* what) {
  fprintf(stderr, "probe: cannot read %s\n", what);
  exit(3);
}

static void readPoints(struct point points[8][8][8], const char* what) {
  for (int i = 0; i < 8; i++)
    for (int j = 0; j < 8; j++)
      for (int k = 0; k < 8; k++) {
        struct point* q = &points[i][j][k];
        if (fscanf(requests, "%lf %lf %lf", &q->x, &q->y, &q->z) != 3) refuse(what);
      }
}

/* Zero nodes before and after the field's: as many as four planes of nodes and then some, so
   that an index one cell (or a little more) beyond the box on any axis stays inside them. */
static size_t fieldPadding(int resolution) {
  size_t r = (size_t)resolution;
  return 4 * r * r + 4 * r + 8;
}

static void readWorldCommand(void) {
  struct world* w = &jello;
  if (fscanf(requests, "%9s", w->integrator) != 1) refuse("the integrator");
  if (fscanf(requests, "%lf %d", &w->dt, &w->n) != 2) refuse("dt n");
  if (fscanf(requests, "%lf %lf %lf %lf", &w->kElastic, &w->dElastic, &w->kCollision,
             &w->dCollision) != 4)
    refuse("the spring constants");
  if (fscanf(requests, "%lf", &w->mass) != 1) refuse("the mass");
  if (fscanf(requests, "%d", &w->incPlanePresent) != 1) refuse("the plane flag");
  if (w->incPlanePresent == 1 &&
      fscanf(requests, "%lf %lf %lf %lf", &w->a, &w->b, &w->c, &w->d) != 4)
    refuse("the plane");
  int resolution = 0;
  if (fscanf(requests, "%d", &resolution) != 1 || resolution < 0 || resolution > 64)
    refuse("the resolution");
  /* The nodes in memory of the grader's, with zeros on either side (fieldPadding): a program
     that reads a cell beyond the box (a point across a wall) reads no force there, as
     physics.md has it, not whatever lies beside the array, so that the walls' checks judge the
     walls. The buffer the student's own readWorld made (in its setup) is kept filled too, for a
     setup that kept that pointer, while the resolution is the same. */
  static struct point* padded = NULL;
  static struct point* students = NULL;
  static int paddedResolution = -1, studentsResolution = -1;
  if (padded == NULL && w->forceField != NULL) { /* the first world: its readWorld's buffer */
    students = w->forceField;
    studentsResolution = w->resolution;
  }
  size_t nodes = (size_t)resolution * (size_t)resolution * (size_t)resolution;
  size_t pad = fieldPadding(resolution);
  if (resolution != paddedResolution) {
    free(padded);
    padded = (struct point*)calloc(nodes + 2 * pad, sizeof(struct point));
    if (!padded) refuse("the field (no memory)");
    paddedResolution = resolution;
  }
  w->forceField = padded + pad;
  w->resolution = resolution;
  for (size_t n = 0; n < nodes; n++) {
    struct point* f = &w->forceField[n];
    if (fscanf(requests, "%lf %lf %lf", &f->x, &f->y, &f->z) != 3) refuse("the field");
    if (students && studentsResolution == resolution) students[n] = *f;
  }
  readPoints(w->p, "the positions");
  readPoints(w->v, "the velocities");
}

static void printPoints(struct point points[8][8][8]) {
  for (int i = 0; i < 8; i++)
    for (int j = 0; j < 8; j++)
      for (int k = 0; k < 8; k++)
        fprintf(answers, "%.17g %.17g %.17g\n", points[i][j][k].x, points[i][j][k].y,
                points[i][j][k].z);
}

static long readCount(void) {
  long n = 0;
  if (fscanf(requests, "%ld", &n) != 1 || n < 0) refuse("a step count");
  return n;
}

/* The program's CPU seconds: the speed a step takes, whatever else the machine runs (a class
   graded two at a time, the grader's own reference runs). */
static double secondsNow(void) {
  struct timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* One RK4 and one Euler step, the world put back after each. */
static void warmUp(void) {
  static struct world saved;
  memcpy(&saved, &jello, sizeof saved);
  RK4(&jello);
  memcpy(&jello, &saved, sizeof saved);
  Euler(&jello);
  memcpy(&jello, &saved, sizeof saved);
}

static struct point accelerations[8][8][8];

static void serve(void) {
  char command[4];
  int warm = 0;
  requests = fdopen(requestFd, "r");
  answers = fdopen(answerFd, "w");
  if (!requests || !answers) exit(4);
  fprintf(answers, "jello-probe\n.\n"); /* the greeting: ready for the first request */
  fflush(answers);
  while (fscanf(requests, "%3s", command) == 1) {
    if (strcmp(command, "W") == 0) {
      readWorldCommand();
      continue;
    }
    if (strcmp(command, "S") == 0) {
      readPoints(jello.p, "the positions");
      readPoints(jello.v, "the velocities");
      continue;
    }
    if (!warm) {
      warm = 1;
      warmUp();
    }
    if (strcmp(command, "A") == 0) {
      memset(accelerations, 0, sizeof accelerations);
      computeAcceleration(&jello, accelerations);
      printPoints(accelerations);
    } else if (strcmp(command, "E") == 0 || strcmp(command, "R") == 0) {
      long steps = readCount();
      for (long s = 0; s < steps; s++) {
        if (command[0] == 'E')
          Euler(&jello);
        else
          RK4(&jello);
      }
      fprintf(answers, "ok\n");
    } else if (strcmp(command, "P") == 0) {
      printPoints(jello.p);
      printPoints(jello.v);
    } else if (strcmp(command, "T") == 0) {
      long steps = readCount();
      double start = secondsNow();
      for (long s = 0; s < steps; s++) RK4(&jello);
      fprintf(answers, "%.17g\n", steps > 0 ? 1e6 * (secondsNow() - start) / (double)steps : 0.0);
    } else {
      refuse("a command");
    }
    fprintf(answers, ".\n");
    fflush(answers);
  }
}

#ifdef JELLO_GRADER_PROGRAM
extern "C" void jello_grader_main_loop(void) {
  fflush(stdout);
  serve();
  exit(0);
}
#else
int main(void) {
  serve();
  return 0;
}
#endif
