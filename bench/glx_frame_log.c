/* LD_PRELOAD shim for the rviz frame-rate measurement (scripts/rviz_fps.sh): every
 * glXSwapBuffers() -- one finished frame of rviz's render window -- appends the CLOCK_MONOTONIC
 * time [s] to the file named by $FRAME_LOG. rviz has no frame-rate readout of its own; counting
 * buffer swaps measures the frames it really draws, without a plugin. Also answers
 * glXGetProcAddress(ARB)("glXSwapBuffers"), in case the renderer looks the function up.
 *   gcc -shared -fPIC -O2 -o glx_frame_log.so glx_frame_log.c -ldl */
#define _GNU_SOURCE
#include <GL/glx.h>
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

typedef void (*SwapFn)(Display*, GLXDrawable);
typedef __GLXextFuncPtr (*ProcFn)(const GLubyte*);

static FILE* frame_log;

static void logFrame(void) {
  if (!frame_log) {
    const char* path = getenv("FRAME_LOG");
    frame_log = fopen(path ? path : "/dev/null", "a");
    if (!frame_log) return;
    setvbuf(frame_log, NULL, _IOLBF, 0);
  }
  struct timespec now;
  clock_gettime(CLOCK_MONOTONIC, &now);
  fprintf(frame_log, "%ld.%09ld\n", (long)now.tv_sec, now.tv_nsec);
}

void glXSwapBuffers(Display* display, GLXDrawable drawable) {
  static SwapFn real;
  if (!real) real = (SwapFn)dlsym(RTLD_NEXT, "glXSwapBuffers");
  real(display, drawable);
  logFrame();
}

static __GLXextFuncPtr lookUp(const char* which, const GLubyte* name) {
  if (strcmp((const char*)name, "glXSwapBuffers") == 0) return (__GLXextFuncPtr)glXSwapBuffers;
  ProcFn real = (ProcFn)dlsym(RTLD_NEXT, which);
  return real ? real(name) : NULL;
}
__GLXextFuncPtr glXGetProcAddress(const GLubyte* name) { return lookUp("glXGetProcAddress", name); }
__GLXextFuncPtr glXGetProcAddressARB(const GLubyte* name) { return lookUp("glXGetProcAddressARB", name); }
