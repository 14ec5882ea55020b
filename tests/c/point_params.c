/* GL 1.4's point parameters (glPointParameter, ARB/EXT_point_parameters) as particle
 * programs used them: sizes attenuated by eye distance (linear and quadratic), clamped to
 * POINT_SIZE_MIN and POINT_SIZE_MAX with and without attenuation, the fade threshold (state
 * only on Mesa), smooth attenuated points, their errors, queries and attribute group; then a
 * field of attenuated points, aliased and smooth, in perspective. Each case prints how many
 * pixels the point covers. Run on Mesa's OSMesa and on fixedfunc's library, the printed
 * lines must be the same and the images match.
 *
 * usage: point_params [out.ppm] */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include "report.h"
#define W 64
#define H 64
static unsigned char *buf;
static int count(void){ glFinish(); int n=0; for(int i=0;i<W*H;i++) if(buf[i*4]) n++; return n; }
static void pt(float z, float a){ glClear(GL_COLOR_BUFFER_BIT); glColor4f(1,1,1,a); glBegin(GL_POINTS); glVertex3f(0.1f,0.13f,z); glEnd(); }
int main(int argc, char **argv){
  const char *out = argc > 1 ? argv[1] : "point_params.ppm";
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  buf = calloc(W*H,4);
  OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H);
  glMatrixMode(GL_PROJECTION); glFrustum(-1,1,-1,1,1,100); glMatrixMode(GL_MODELVIEW);
  glPointSize(10);
  float zs[] = {-1.5f, -3, -6};
  for (int k=0;k<3;k++){ pt(zs[k],1); printf("plain z %g: %d\n", zs[k], count()); }
  glPointParameterf(GL_POINT_SIZE_MAX, 4); for (int k=0;k<1;k++){ pt(zs[k],1); printf("max 4 no atten: %d err %x\n", count(), glGetError()); }
  glPointParameterf(GL_POINT_SIZE_MAX, 255); glPointParameterf(GL_POINT_SIZE_MIN, 12); pt(-3,1); printf("min 12 no atten: %d\n", count());
  glPointParameterf(GL_POINT_SIZE_MIN, 0);
  GLfloat att[3] = {0, 0.5f, 0}; glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, att);
  for (int k=0;k<3;k++){ pt(zs[k],1); printf("atten linear z %g: %d\n", zs[k], count()); }
  GLfloat att2[3] = {0.2f, 0.1f, 0.05f}; glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, att2);
  for (int k=0;k<3;k++){ pt(zs[k],1); printf("atten quad z %g: %d\n", zs[k], count()); }
  glPointParameterf(GL_POINT_SIZE_MAX, 5); pt(-1.5f,1); printf("atten max5: %d\n", count());
  glPointParameterf(GL_POINT_SIZE_MAX, 255); glPointParameterf(GL_POINT_SIZE_MIN, 6); pt(-6,1); printf("atten min6: %d\n", count());
  glPointParameterf(GL_POINT_SIZE_MIN, 0);
  glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 20); glEnable(GL_BLEND); glBlendFunc(GL_SRC_ALPHA, GL_ONE);
  pt(-6,1); glFinish(); int mx=0; for(int i=0;i<W*H;i++) if(buf[i*4]>mx) mx=buf[i*4]; printf("fade 20: %d max %d\n", count(), mx);
  glDisable(GL_BLEND);
  glEnable(GL_POINT_SMOOTH); for (int k=0;k<3;k++){ pt(zs[k],1); printf("smooth atten z %g: %d\n", zs[k], count()); }
  glPointSize(1); pt(-6,1); printf("smooth atten size1 z -6: %d\n", count());
  glDisable(GL_POINT_SMOOTH);
  glPointParameterf(GL_POINT_SIZE_MIN, -1); printf("min -1 err %x\n", glGetError());
  glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, -1); printf("fade -1 err %x\n", glGetError());
  glPointParameterf(GL_POINT_SIZE_MAX, -1); printf("max -1 err %x\n", glGetError());
  glPointParameterf(0x8CA0, GL_LOWER_LEFT); printf("coord origin err %x\n", glGetError());
  glPointParameterf(GL_FOG_START, 1); printf("bad pname err %x\n", glGetError());
  glPointParameteri(GL_POINT_SIZE_MIN, 3); GLfloat v[3]; glGetFloatv(GL_POINT_SIZE_MIN, v); printf("i min %g err %x\n", v[0], glGetError());
  glPointParameterf(GL_POINT_SIZE_MIN, 8); glPointParameterf(GL_POINT_SIZE_MAX, 2); glGetFloatv(GL_POINT_SIZE_MAX, v); printf("min>max: %g err %x\n", v[0], glGetError());
  glPushAttrib(GL_POINT_BIT); glPointParameterf(GL_POINT_SIZE_MIN, 1); glPopAttrib(); glGetFloatv(GL_POINT_SIZE_MIN, v); printf("pop min %g\n", v[0]);
  GLfloat q[3] = {-1, -1, -1};
  glGetFloatv(GL_POINT_DISTANCE_ATTENUATION, q); printf("attenuation %g %g %g err %x\n", q[0], q[1], q[2], glGetError());
  glPointParameterf(0x8CA0, GL_ZERO); printf("bad coord origin err %x\n", glGetError());

  /* A field of attenuated points in perspective: aliased on the left, smooth on the right. */
  glPointParameterf(GL_POINT_SIZE_MIN, 1);
  glPointParameterf(GL_POINT_SIZE_MAX, 14);
  GLfloat field[3] = {0, 0.3f, 0.02f};
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, field);
  glClearColor(0.1f, 0.1f, 0.15f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glPointSize(9);
  for (int side = 0; side < 2; side++) {
    if (side) glEnable(GL_POINT_SMOOTH);
    glBegin(GL_POINTS);
    for (int i = 0; i < 12; i++) {
      float z = -1.2f - 0.9f * (float)i;
      glColor4f(1, 0.4f + 0.05f * (float)i, 0.2f, side ? 0.8f : 1);
      glVertex3f((side ? 0.35f : -0.65f) * -z + 0.07f * (float)(i % 3), (-0.8f + 0.14f * (float)i) * -z, z);
    }
    glEnd();
  }
  glFinish();
  if (!write_ppm(out, buf, W, H)) return 1;
  OSMesaDestroyContext(ctx);
  free(buf);
  return 0;
}
