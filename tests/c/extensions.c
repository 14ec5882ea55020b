/* The extensions of the 1990s and early 2000s that name, under their own entry points and
 * tokens, what GL 1.2–1.4 made core — blend colour, equations and separate factors,
 * range and multi draws, the GL 1.1 texture calls, rescaled normals, reflection texgen,
 * shadow compare functions, ADD, border clamp, mirrored repeat, packed pixels,
 * multisample state — as a program of the time meets them: the extension string checked,
 * each entry point found with OSMesaGetProcAddress and called through it, each token
 * used. Then panels blended through the extension entry points. Run on Mesa's OSMesa and
 * on fixedfunc's library, the printed lines must be the same and the images match.
 *
 * usage: extensions [out.ppm] */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include "report.h"
#define W 96
#define H 32

static const char *const EXTENSIONS[] = {
    "GL_APPLE_packed_pixels",       "GL_ARB_multisample",
    "GL_EXT_blend_color",           "GL_EXT_blend_func_separate",
    "GL_EXT_blend_minmax",          "GL_EXT_blend_subtract",
    "GL_EXT_copy_texture",          "GL_EXT_draw_range_elements",
    "GL_EXT_multi_draw_arrays",     "GL_EXT_rescale_normal",
    "GL_EXT_shadow_funcs",          "GL_EXT_subtexture",
    "GL_EXT_texture_env_add",       "GL_EXT_texture_object",
    "GL_IBM_texture_mirrored_repeat", "GL_INGR_blend_func_separate",
    "GL_NV_blend_square",           "GL_NV_texgen_reflection",
    "GL_SGIS_texture_border_clamp", NULL};

static const char *const ENTRY_POINTS[] = {
    "glBlendColorEXT",        "glBlendEquationEXT",       "glBlendFuncSeparateEXT",
    "glBlendFuncSeparateINGR", "glDrawRangeElementsEXT",  "glMultiDrawArraysEXT",
    "glMultiDrawElementsEXT", "glCopyTexImage1DEXT",      "glCopyTexImage2DEXT",
    "glCopyTexSubImage1DEXT", "glCopyTexSubImage2DEXT",   "glCopyTexSubImage3DEXT",
    "glTexSubImage1DEXT",     "glTexSubImage2DEXT",       "glAreTexturesResidentEXT",
    "glBindTextureEXT",       "glDeleteTexturesEXT",      "glGenTexturesEXT",
    "glIsTextureEXT",         "glPrioritizeTexturesEXT",  "glSampleCoverageARB",
    NULL};

typedef void (*BlendColor)(GLfloat, GLfloat, GLfloat, GLfloat);
typedef void (*BlendEquation)(GLenum);
typedef void (*BlendFuncSeparate)(GLenum, GLenum, GLenum, GLenum);
typedef void (*DrawRangeElements)(GLenum, GLuint, GLuint, GLsizei, GLenum, const void *);
typedef void (*MultiDrawArrays)(GLenum, const GLint *, const GLsizei *, GLsizei);
typedef void (*GenTextures)(GLsizei, GLuint *);
typedef void (*BindTexture)(GLenum, GLuint);
typedef GLboolean (*IsTexture)(GLuint);
typedef void (*TexSubImage2D)(GLenum, GLint, GLint, GLint, GLsizei, GLsizei, GLenum, GLenum,
                              const void *);
typedef void (*CopyTexSubImage2D)(GLenum, GLint, GLint, GLint, GLint, GLint, GLsizei, GLsizei);
typedef void (*SampleCoverage)(GLclampf, GLboolean);

/* A square of window units over panel k of 8, in the current colour. */
static void panel(int k, GLfloat r, GLfloat g, GLfloat b, GLfloat a) {
  glColor4f(r, g, b, a);
  glRecti(k * 12 + 1, 2, k * 12 + 11, 30);
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "extensions.ppm";
  OSMesaContext ctx;
  GLubyte *buf = open_window(&ctx, W, H); /* glOrtho(0, W, 0, H): a unit is a pixel */
  if (!buf) return 1;
  for (int i = 0; EXTENSIONS[i]; i++)
    printf("%-32s named %d\n", EXTENSIONS[i], extension_named(EXTENSIONS[i]));
  for (int i = 0; ENTRY_POINTS[i]; i++)
    printf("%-32s found %d\n", ENTRY_POINTS[i], OSMesaGetProcAddress(ENTRY_POINTS[i]) != NULL);

  BlendColor blend_color = (BlendColor)OSMesaGetProcAddress("glBlendColorEXT");
  BlendEquation blend_equation = (BlendEquation)OSMesaGetProcAddress("glBlendEquationEXT");
  BlendFuncSeparate separate = (BlendFuncSeparate)OSMesaGetProcAddress("glBlendFuncSeparateEXT");
  BlendFuncSeparate separate_ingr =
      (BlendFuncSeparate)OSMesaGetProcAddress("glBlendFuncSeparateINGR");
  DrawRangeElements range = (DrawRangeElements)OSMesaGetProcAddress("glDrawRangeElementsEXT");
  MultiDrawArrays multi = (MultiDrawArrays)OSMesaGetProcAddress("glMultiDrawArraysEXT");
  GenTextures gen = (GenTextures)OSMesaGetProcAddress("glGenTexturesEXT");
  BindTexture bind = (BindTexture)OSMesaGetProcAddress("glBindTextureEXT");
  /* Through void (*)(void): the entry point returns a GLboolean, not void. */
  IsTexture is_texture = (IsTexture)(void (*)(void))OSMesaGetProcAddress("glIsTextureEXT");
  TexSubImage2D sub = (TexSubImage2D)OSMesaGetProcAddress("glTexSubImage2DEXT");
  CopyTexSubImage2D copy_sub = (CopyTexSubImage2D)OSMesaGetProcAddress("glCopyTexSubImage2DEXT");
  SampleCoverage coverage = (SampleCoverage)OSMesaGetProcAddress("glSampleCoverageARB");
  if (!blend_color || !blend_equation || !separate || !separate_ingr || !range || !multi ||
      !gen || !bind || !is_texture || !sub || !copy_sub || !coverage)
    return 1;

  /* The tokens, each taken without an error. */
  blend_color(0.25f, 0.5f, 0.75f, 0.5f);
  err("glBlendColorEXT");
  GLenum equations[4] = {GL_MIN_EXT, GL_MAX_EXT, GL_FUNC_SUBTRACT_EXT,
                         GL_FUNC_REVERSE_SUBTRACT_EXT};
  for (int i = 0; i < 4; i++) blend_equation(equations[i]);
  err("glBlendEquationEXT MIN MAX SUBTRACT REVERSE");
  blend_equation(GL_ZERO);
  err("glBlendEquationEXT ZERO");
  separate(GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_DST_COLOR, GL_ONE);
  err("glBlendFuncSeparateEXT");
  ints("BLEND_SRC_RGB_EXT", GL_BLEND_SRC_RGB_EXT);
  ints("BLEND_DST_ALPHA_EXT", GL_BLEND_DST_ALPHA_EXT);
  ints("BLEND_EQUATION_EXT", GL_BLEND_EQUATION_EXT);
  GLfloat color[4] = {-1, -1, -1, -1};
  glGetFloatv(GL_BLEND_COLOR_EXT, color);
  printf("BLEND_COLOR_EXT %g %g %g %g err 0x%x\n", color[0], color[1], color[2], color[3],
         glGetError());
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP_NV);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP_NV);
  err("texgen REFLECTION_MAP_NV NORMAL_MAP_NV");
  GLenum funcs[8] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL,
                     GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
  for (int i = 0; i < 8; i++) glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, funcs[i]);
  err("the eight compare functions");
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
  err("TEXTURE_ENV_MODE ADD");
  glEnable(GL_RESCALE_NORMAL_EXT);
  ints("RESCALE_NORMAL_EXT", GL_RESCALE_NORMAL_EXT);
  glDisable(GL_RESCALE_NORMAL_EXT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER_SGIS);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_MIRRORED_REPEAT_IBM);
  err("CLAMP_TO_BORDER_SGIS MIRRORED_REPEAT_IBM");
  coverage(0.5f, GL_TRUE);
  err("glSampleCoverageARB");
  GLfloat value = -1;
  glGetFloatv(GL_SAMPLE_COVERAGE_VALUE_ARB, &value);
  printf("SAMPLE_COVERAGE_VALUE_ARB %g err 0x%x\n", value, glGetError());
  ints("SAMPLE_BUFFERS_ARB", GL_SAMPLE_BUFFERS_ARB);
  ints("MULTISAMPLE_ARB", GL_MULTISAMPLE_ARB);

  /* The texture-object and sub-image calls through their EXT names. */
  GLuint tex = 0;
  gen(1, &tex);
  bind(GL_TEXTURE_2D, tex);
  printf("glIsTextureEXT %d err 0x%x\n", is_texture(tex), glGetError());
  static const GLushort texels[4] = {0xF00F, 0x0F0F, 0x00FF, 0xFFFF}; /* RGBA 4444 */
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4_EXT,
               texels);
  sub(GL_TEXTURE_2D, 0, 1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4_EXT, texels);
  err("glTexSubImage2DEXT of 4_4_4_4_EXT texels");
  copy_sub(GL_TEXTURE_2D, 0, 0, 0, 0, 0, 1, 1);
  err("glCopyTexSubImage2DEXT");

  /* Panels: blending through the EXT entry points over a grey background. */
  glClearColor(0.4f, 0.4f, 0.4f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_BLEND);
  blend_equation(GL_FUNC_ADD_EXT);
  glBlendFunc(GL_CONSTANT_COLOR_EXT, GL_ONE_MINUS_CONSTANT_ALPHA_EXT);
  panel(0, 1, 1, 1, 1);
  blend_equation(GL_MIN_EXT);
  panel(1, 0.9f, 0.2f, 0.6f, 1);
  blend_equation(GL_MAX_EXT);
  panel(2, 0.9f, 0.2f, 0.6f, 1);
  blend_equation(GL_FUNC_REVERSE_SUBTRACT_EXT);
  glBlendFunc(GL_ONE, GL_ONE);
  panel(3, 0.1f, 0.3f, 0.2f, 1);
  blend_equation(GL_FUNC_ADD_EXT);
  separate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
  panel(4, 0.9f, 0.8f, 0.1f, 0.6f);
  separate_ingr(GL_SRC_COLOR, GL_DST_COLOR, GL_ONE, GL_ZERO);
  panel(5, 0.5f, 0.9f, 0.3f, 1);
  glBlendFunc(GL_DST_COLOR, GL_SRC_COLOR); /* NV_blend_square: both factors colours */
  panel(6, 0.8f, 0.3f, 0.9f, 1);
  glDisable(GL_BLEND);

  /* Range and multi draws of two triangles in the last panel. */
  static const GLfloat corners[12] = {85, 2, 95, 2, 85, 15, 85, 17, 95, 17, 95, 30};
  static const GLubyte order[6] = {0, 1, 2, 3, 4, 5};
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, corners);
  glColor3f(0.2f, 0.9f, 0.9f);
  range(GL_TRIANGLES, 0, 2, 3, GL_UNSIGNED_BYTE, order);
  static const GLint first[1] = {3};
  static const GLsizei count[1] = {3};
  glColor3f(0.9f, 0.9f, 0.2f);
  multi(GL_TRIANGLES, first, count, 1);
  glDisableClientState(GL_VERTEX_ARRAY);
  err("the panels");
  return finish(out, ctx, buf, W, H);
}
