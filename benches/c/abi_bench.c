/* The workload of `fixedfunc bench --only abi`: a program of the OSMesa era, compiled against
 * Mesa's GL/osmesa.h and run unchanged on Mesa's libOSMesa.so.8 and on fixedfunc's.
 *
 * A 256x256 RGBA buffer with 24 depth and 8 stencil bits. Each frame clears, draws a fixed
 * workload and ends in glFinish; each frame's time is printed. The geometry modes draw a
 * 4x4 grid of lit spheres (48 slices x 24 stacks, GL_TRIANGLES: 6912 vertices each, 16
 * draws, 110592 vertices a frame) through one of the era's paths:
 *
 *   immediate  glBegin/glNormal3fv/glVertex3fv/glEnd
 *   arrays     client vertex and normal arrays, glDrawElements of GL_UNSIGNED_SHORT
 *   lists      one display list compiled from the immediate calls, glCallList per sphere
 *   buffers    the arrays in GL 1.5 buffer objects (vertex and element array buffers)
 *   shadow     a depth-texture shadow map as in 2000: the spheres over a ground grid drawn
 *              from the light into the buffer (colour writes off, polygon offset), copied
 *              with glCopyTexImage2D into a DEPTH_COMPONENT texture compared with
 *              COMPARE_R_TO_TEXTURE, then drawn from the eye, lit, with eye-linear texgen
 *              (S,T,R,Q) and the texture matrix bias * light projection * light view
 *
 * Output, one record per line, fields separated by spaces:
 *   vendor TEXT | renderer TEXT | mode NAME | vertices N (per frame) | draws N (per frame)
 *   frame I MS (one per frame) | drawn N (pixels not of the clear colour) | dark N | lit N
 *   mean R G B (over the whole image) | errors 0
 * Exit status: 0; 2 for a bad command line; 3 when the context cannot be made; 4 for a GL
 * error; 5 when the image does not show the workload (nothing drawn, or no shadow).
 *
 * usage: abi_bench MODE FRAMES [OUT.ppm] */
#define _POSIX_C_SOURCE 199309L
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/glext.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define W 256
#define H 256
#define SLICES 48
#define STACKS 24
#define SPHERE_VERTS ((SLICES + 1) * (STACKS + 1))
#define SPHERE_INDICES (6 * SLICES * STACKS)
#define GRID 4
#define GROUND_CELLS 32
#define GROUND_VERTS ((GROUND_CELLS + 1) * (GROUND_CELLS + 1))
#define GROUND_INDICES (6 * GROUND_CELLS * GROUND_CELLS)

enum mode { IMMEDIATE, ARRAYS, LISTS, BUFFERS, SHADOW };
static const char *const MODE_NAMES[] = {"immediate", "arrays", "lists", "buffers", "shadow"};

static const float PI = 3.14159265358979f;

/* One mesh: positions and normals (3 floats each) and triangle indices. */
struct mesh {
  GLfloat *xyz, *normal;
  GLushort *index;
  int verts, indices;
};

static void *must_alloc(size_t bytes) {
  void *p = malloc(bytes);
  if (!p) {
    fprintf(stderr, "out of memory\n");
    exit(3);
  }
  return p;
}

static struct mesh mesh_alloc(int verts, int indices) {
  struct mesh m;
  m.xyz = must_alloc(sizeof(GLfloat) * 3 * verts);
  m.normal = must_alloc(sizeof(GLfloat) * 3 * verts);
  m.index = must_alloc(sizeof(GLushort) * indices);
  m.verts = verts;
  m.indices = indices;
  return m;
}

/* A unit sphere: vertex (i, j) at longitude 2*pi*i/SLICES, latitude pi*j/STACKS; two
 * triangles per cell (the cells at the poles have one degenerate triangle each). */
static struct mesh sphere(void) {
  struct mesh m = mesh_alloc(SPHERE_VERTS, SPHERE_INDICES);
  for (int j = 0; j <= STACKS; j++) {
    for (int i = 0; i <= SLICES; i++) {
      float lon = 2 * PI * i / SLICES, lat = PI * j / STACKS;
      GLfloat *n = m.normal + 3 * (j * (SLICES + 1) + i);
      n[0] = sinf(lat) * cosf(lon);
      n[1] = cosf(lat);
      n[2] = sinf(lat) * sinf(lon);
      memcpy(m.xyz + 3 * (j * (SLICES + 1) + i), n, sizeof(GLfloat) * 3);
    }
  }
  GLushort *p = m.index;
  for (int j = 0; j < STACKS; j++) {
    for (int i = 0; i < SLICES; i++) {
      GLushort a = (GLushort)(j * (SLICES + 1) + i), b = (GLushort)(a + SLICES + 1);
      *p++ = a, *p++ = (GLushort)(a + 1), *p++ = b;
      *p++ = (GLushort)(a + 1), *p++ = (GLushort)(b + 1), *p++ = b;
    }
  }
  return m;
}

/* The ground: a grid over [-2, 2]^2 in the plane y = 0, facing up. */
static struct mesh ground(void) {
  struct mesh m = mesh_alloc(GROUND_VERTS, GROUND_INDICES);
  for (int j = 0; j <= GROUND_CELLS; j++) {
    for (int i = 0; i <= GROUND_CELLS; i++) {
      GLfloat *v = m.xyz + 3 * (j * (GROUND_CELLS + 1) + i);
      GLfloat *n = m.normal + 3 * (j * (GROUND_CELLS + 1) + i);
      v[0] = -2 + 4.0f * i / GROUND_CELLS, v[1] = 0, v[2] = -2 + 4.0f * j / GROUND_CELLS;
      n[0] = 0, n[1] = 1, n[2] = 0;
    }
  }
  GLushort *p = m.index;
  for (int j = 0; j < GROUND_CELLS; j++) {
    for (int i = 0; i < GROUND_CELLS; i++) {
      GLushort a = (GLushort)(j * (GROUND_CELLS + 1) + i), b = (GLushort)(a + GROUND_CELLS + 1);
      *p++ = a, *p++ = b, *p++ = (GLushort)(a + 1);
      *p++ = (GLushort)(a + 1), *p++ = b, *p++ = (GLushort)(b + 1);
    }
  }
  return m;
}

static void draw_immediate(const struct mesh *m) {
  glBegin(GL_TRIANGLES);
  for (int k = 0; k < m->indices; k++) {
    glNormal3fv(m->normal + 3 * m->index[k]);
    glVertex3fv(m->xyz + 3 * m->index[k]);
  }
  glEnd();
}

static void arrays_from(const struct mesh *m) {
  glVertexPointer(3, GL_FLOAT, 0, m->xyz);
  glNormalPointer(GL_FLOAT, 0, m->normal);
}

/* Sphere k of the grid: centres 0.5 apart, radius 0.22 (geometry modes, in view space), or
 * 0.9 apart at height 0.5, radius 0.3 (shadow mode, on the ground). */
static void place(enum mode mode, int k) {
  float x = (float)(k % GRID) - 1.5f, y = (float)(k / GRID) - 1.5f;
  if (mode == SHADOW) {
    glTranslatef(0.9f * x, 0.5f, 0.9f * y);
    glScalef(0.3f, 0.3f, 0.3f);
  } else {
    glTranslatef(0.5f * x, 0.5f * y, 0);
    glScalef(0.22f, 0.22f, 0.22f);
  }
}

/* gluLookAt's matrix (column-major), written out because the program links no GLU. */
static void look_at(GLfloat m[16], const float eye[3], const float at[3]) {
  float f[3] = {at[0] - eye[0], at[1] - eye[1], at[2] - eye[2]}, up[3] = {0, 1, 0};
  float fl = sqrtf(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
  for (int i = 0; i < 3; i++) f[i] /= fl;
  float s[3] = {f[1] * up[2] - f[2] * up[1], f[2] * up[0] - f[0] * up[2],
                f[0] * up[1] - f[1] * up[0]};
  float sl = sqrtf(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
  for (int i = 0; i < 3; i++) s[i] /= sl;
  float u[3] = {s[1] * f[2] - s[2] * f[1], s[2] * f[0] - s[0] * f[2], s[0] * f[1] - s[1] * f[0]};
  memset(m, 0, sizeof(GLfloat) * 16);
  for (int i = 0; i < 3; i++) {
    m[4 * i] = s[i], m[4 * i + 1] = u[i], m[4 * i + 2] = -f[i];
  }
  m[12] = -(s[0] * eye[0] + s[1] * eye[1] + s[2] * eye[2]);
  m[13] = -(u[0] * eye[0] + u[1] * eye[1] + u[2] * eye[2]);
  m[14] = f[0] * eye[0] + f[1] * eye[1] + f[2] * eye[2];
  m[15] = 1;
}

static const float LIGHT_EYE[3] = {1.5f, 5, 2}, CAMERA_EYE[3] = {0, 3.5f, 5.5f},
                   ORIGIN[3] = {0, 0, 0};

static void light_projection(void) { glFrustum(-0.5, 0.5, -0.5, 0.5, 1.5, 12); }

static void lights_on(const float position[4]) {
  static const GLfloat white[] = {1, 1, 1, 1}, ambient[] = {0.15f, 0.15f, 0.15f, 1};
  static const GLfloat material[] = {0.85f, 0.6f, 0.3f, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, material);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, white);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 32);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHTING);
}

struct scene {
  enum mode mode;
  struct mesh sphere, ground;
  GLuint list, buffers[2], texture;
};

/* Draws the 16 spheres through the mode's path (the shadow mode draws arrays). */
static void spheres(const struct scene *s) {
  for (int k = 0; k < GRID * GRID; k++) {
    glPushMatrix();
    place(s->mode, k);
    switch (s->mode) {
    case IMMEDIATE: draw_immediate(&s->sphere); break;
    case LISTS: glCallList(s->list); break;
    case BUFFERS: glDrawElements(GL_TRIANGLES, SPHERE_INDICES, GL_UNSIGNED_SHORT, (const GLvoid *)0); break;
    case ARRAYS:
    case SHADOW: glDrawElements(GL_TRIANGLES, SPHERE_INDICES, GL_UNSIGNED_SHORT, s->sphere.index); break;
    }
    glPopMatrix();
  }
}

static void shadow_scene(const struct scene *s) {
  arrays_from(&s->ground);
  glDrawElements(GL_TRIANGLES, GROUND_INDICES, GL_UNSIGNED_SHORT, s->ground.index);
  arrays_from(&s->sphere);
  spheres(s);
}

static void setup(struct scene *s) {
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  glEnable(GL_NORMALIZE); /* the spheres are scaled: their normals are not unit */
  glClearColor(64 / 255.0f, 96 / 255.0f, 128 / 255.0f, 1);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  arrays_from(&s->sphere);
  if (s->mode == LISTS) {
    s->list = glGenLists(1);
    glNewList(s->list, GL_COMPILE);
    draw_immediate(&s->sphere);
    glEndList();
  } else if (s->mode == BUFFERS) {
    glGenBuffers(2, s->buffers);
    glBindBuffer(GL_ARRAY_BUFFER, s->buffers[0]);
    glBufferData(GL_ARRAY_BUFFER, sizeof(GLfloat) * 6 * SPHERE_VERTS, NULL, GL_STATIC_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof(GLfloat) * 3 * SPHERE_VERTS, s->sphere.xyz);
    glBufferSubData(GL_ARRAY_BUFFER, sizeof(GLfloat) * 3 * SPHERE_VERTS,
                    sizeof(GLfloat) * 3 * SPHERE_VERTS, s->sphere.normal);
    glVertexPointer(3, GL_FLOAT, 0, (const GLvoid *)0);
    glNormalPointer(GL_FLOAT, 0, (const GLvoid *)(sizeof(GLfloat) * 3 * SPHERE_VERTS));
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, s->buffers[1]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof(GLushort) * SPHERE_INDICES, s->sphere.index,
                 GL_STATIC_DRAW);
  } else if (s->mode == SHADOW) {
    glGenTextures(1, &s->texture);
    glBindTexture(GL_TEXTURE_2D, s->texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE_ARB, GL_COMPARE_R_TO_TEXTURE_ARB);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC_ARB, GL_LEQUAL);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glPolygonOffset(2, 4);
  }
}

static void geometry_frame(const struct scene *s) {
  static const GLfloat light[] = {0.4f, 0.6f, 1, 0};
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.1, 0.1, -0.1, 0.1, 0.3, 10);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  lights_on(light);
  glTranslatef(0, 0, -3);
  spheres(s);
}

/* Light pass, copy, eye pass. Eye planes are set with the camera's view on the modelview
 * stack, so S,T,R,Q generate world coordinates; the texture matrix takes them to the
 * light's window space: T(1/2) S(1/2) P_light V_light. */
static void shadow_frame(const struct scene *s) {
  GLfloat light_view[16], camera_view[16];
  look_at(light_view, LIGHT_EYE, ORIGIN);
  look_at(camera_view, CAMERA_EYE, ORIGIN);

  glClear(GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  light_projection();
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixf(light_view);
  glDisable(GL_LIGHTING);
  glDisable(GL_TEXTURE_2D);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  shadow_scene(s);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 0, 0, W, H, 0);

  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.3, 0.3, -0.3, 0.3, 1, 20);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glTranslatef(0.5f, 0.5f, 0.5f);
  glScalef(0.5f, 0.5f, 0.5f);
  light_projection();
  glMultMatrixf(light_view);
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixf(camera_view);
  const GLfloat position[] = {LIGHT_EYE[0], LIGHT_EYE[1], LIGHT_EYE[2], 1};
  lights_on(position);
  static const GLenum coords[] = {GL_S, GL_T, GL_R, GL_Q};
  static const GLenum enables[] = {GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R,
                                   GL_TEXTURE_GEN_Q};
  for (int i = 0; i < 4; i++) {
    GLfloat plane[4] = {0, 0, 0, 0};
    plane[i] = 1;
    glTexGeni(coords[i], GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glTexGenfv(coords[i], GL_EYE_PLANE, plane);
    glEnable(enables[i]);
  }
  glEnable(GL_TEXTURE_2D);
  shadow_scene(s);
  for (int i = 0; i < 4; i++) glDisable(enables[i]);
}

static double now_ms(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

static int write_ppm(const char *path, const GLubyte *rgba) {
  FILE *f = fopen(path, "wb");
  if (!f) return 0;
  fprintf(f, "P6\n%d %d\n255\n", W, H);
  for (int y = H - 1; y >= 0; y--)
    for (int x = 0; x < W; x++) fwrite(rgba + 4 * (y * W + x), 1, 3, f);
  return fclose(f) == 0;
}

/* What the last frame shows: pixels not of the clear colour (drawn), drawn ones darker
 * than 16 in every channel (dark: in shadow) or brighter than 96 in one (lit), and the
 * mean of each channel. Returns 0 when the image cannot be the workload. */
static int judge(enum mode mode, const GLubyte *rgba) {
  long drawn = 0, dark = 0, lit = 0, sum[3] = {0, 0, 0};
  for (int i = 0; i < W * H; i++) {
    const GLubyte *p = rgba + 4 * i;
    for (int c = 0; c < 3; c++) sum[c] += p[c];
    if (p[0] == 64 && p[1] == 96 && p[2] == 128) continue;
    drawn++;
    if (p[0] < 16 && p[1] < 16 && p[2] < 16) dark++;
    if (p[0] > 96 || p[1] > 96 || p[2] > 96) lit++;
  }
  printf("drawn %ld\ndark %ld\nlit %ld\n", drawn, dark, lit);
  printf("mean %.3f %.3f %.3f\n", sum[0] / (double)(W * H), sum[1] / (double)(W * H),
         sum[2] / (double)(W * H));
  if (drawn < W * H / 10 || lit < W * H / 20) {
    fprintf(stderr, "the image does not show the workload (%ld pixels drawn, %ld lit)\n",
            drawn, lit);
    return 0;
  }
  if (mode == SHADOW && dark < W * H / 100) {
    fprintf(stderr, "the shadow frame has no shadow (%ld dark pixels)\n", dark);
    return 0;
  }
  return 1;
}

int main(int argc, char **argv) {
  int mode = -1, frames = argc > 2 ? atoi(argv[2]) : 0;
  for (int i = 0; argc > 1 && i < 5; i++)
    if (strcmp(argv[1], MODE_NAMES[i]) == 0) mode = i;
  if (argc < 3 || argc > 4 || mode < 0 || frames < 1 || frames > 100000) {
    fprintf(stderr,
            "usage: %s MODE FRAMES [OUT.ppm]; MODE is immediate, arrays, lists, buffers or "
            "shadow; FRAMES 1 to 100000\n",
            argv[0]);
    return 2;
  }
  static GLubyte buffer[W * H * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, W, H)) {
    fprintf(stderr, "cannot create an OSMesa context\n");
    return 3;
  }
  printf("vendor %s\nrenderer %s\nmode %s\n", (const char *)glGetString(GL_VENDOR),
         (const char *)glGetString(GL_RENDERER), MODE_NAMES[mode]);
  struct scene s;
  memset(&s, 0, sizeof s);
  s.mode = (enum mode)mode;
  s.sphere = sphere();
  s.ground = ground();
  setup(&s);
  int per_pass = GRID * GRID * SPHERE_INDICES, draws = GRID * GRID;
  if (mode == SHADOW) per_pass += GROUND_INDICES, draws += 1;
  printf("vertices %d\ndraws %d\n", mode == SHADOW ? 2 * per_pass : per_pass,
         mode == SHADOW ? 2 * draws : draws);
  for (int f = 0; f < frames; f++) {
    double t0 = now_ms();
    if (mode == SHADOW)
      shadow_frame(&s);
    else
      geometry_frame(&s);
    glFinish();
    printf("frame %d %.4f\n", f, now_ms() - t0);
  }
  GLenum error = glGetError();
  if (error != GL_NO_ERROR) {
    fprintf(stderr, "GL error 0x%04x after the frames\n", (unsigned)error);
    return 4;
  }
  if (!judge(s.mode, buffer)) return 5;
  if (argc == 4 && !write_ppm(argv[3], buffer)) {
    fprintf(stderr, "cannot write %s\n", argv[3]);
    return 2;
  }
  printf("errors 0\n");
  OSMesaDestroyContext(ctx);
  return 0;
}
