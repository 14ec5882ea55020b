/* Where llvmpipe's rasterizer threads may run after a frame has been drawn: for the
 * process, then for each thread named llvmpipe-K, the CPUs of its affinity mask as
 * /proc lists them (Cpus_allowed_list), one record per line:
 *   process CPUS
 *   llvmpipe-K CPUS          (sorted by K)
 * Exit status: 0; 3 when the context cannot be made. */
#define _DEFAULT_SOURCE
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "report.h"

#define W 64
#define H 64
#define MAX_THREADS 64

/* The Cpus_allowed_list field of a /proc status file, into `out` (empty when absent). */
static void allowed_list(const char *status_path, char *out, size_t size) {
  out[0] = 0;
  FILE *f = fopen(status_path, "r");
  if (!f) return;
  char line[512];
  while (fgets(line, sizeof line, f)) {
    if (strncmp(line, "Cpus_allowed_list:", 18) == 0) {
      const char *v = line + 18;
      while (*v == ' ' || *v == '\t') v++;
      snprintf(out, size, "%s", v);
      out[strcspn(out, "\n")] = 0;
    }
  }
  fclose(f);
}

int main(void) {
  OSMesaContext ctx;
  GLubyte *pixels = open_window(&ctx, W, H);
  if (!pixels) return 3;
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  glVertex2i(4, 4);
  glVertex2i(W - 4, 4);
  glVertex2i(W / 2, H - 4);
  glEnd();
  glFinish();

  char list[256];
  allowed_list("/proc/self/status", list, sizeof list);
  printf("process %s\n", list);
  char lines[MAX_THREADS][400];
  int k_of[MAX_THREADS], n = 0;
  DIR *dir = opendir("/proc/self/task");
  struct dirent *e;
  while (dir && (e = readdir(dir)) && n < MAX_THREADS) {
    if (e->d_name[0] == '.') continue;
    char path[300], comm[64] = "";
    snprintf(path, sizeof path, "/proc/self/task/%s/comm", e->d_name);
    FILE *f = fopen(path, "r");
    if (!f) continue;
    if (!fgets(comm, sizeof comm, f)) comm[0] = 0;
    fclose(f);
    comm[strcspn(comm, "\n")] = 0;
    if (strncmp(comm, "llvmpipe-", 9) != 0) continue;
    snprintf(path, sizeof path, "/proc/self/task/%s/status", e->d_name);
    allowed_list(path, list, sizeof list);
    k_of[n] = atoi(comm + 9);
    snprintf(lines[n], sizeof lines[n], "%s %s", comm, list);
    n++;
  }
  if (dir) closedir(dir);
  for (int k = 0; k < MAX_THREADS; k++)
    for (int i = 0; i < n; i++)
      if (k_of[i] == k) printf("%s\n", lines[i]);
  OSMesaDestroyContext(ctx);
  free(pixels);
  return 0;
}
