/* OSMesaGetProcAddress of the extension names the registry makes aliases of GL 1.x calls
 * (glBlendEquationEXT is glBlendEquation, glActiveTextureARB glActiveTexture …) and of
 * EXT_texture_object's names, as a program of the era fetches them: each found, then the
 * blend equation set through the EXT name and read back, and a texture bound through
 * glBindTextureEXT.
 *
 * usage: proc_aliases */
#include <GL/osmesa.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>

int main(void) {
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  GLubyte *buf = calloc(4 * 4, 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 4, 4)) return 2;
  static const char *const names[] = {
      "glBlendEquationEXT",       "glBlendColorEXT",           "glBindTextureEXT",
      "glDrawArraysEXT",          "glArrayElementEXT",         "glDrawRangeElementsEXT",
      "glMultiDrawArraysEXT",     "glActiveTextureARB",        "glClientActiveTextureARB",
      "glMultiTexCoord2fARB",     "glLoadTransposeMatrixfARB", "glPointParameterfARB",
      "glFogCoordfEXT",           "glSecondaryColor3fEXT",     "glGenBuffersARB",
      "glBindBufferARB",          "glBufferDataARB",           "glBlendFuncSeparateEXT",
      "glCompressedTexImage2DARB", "glSampleCoverageARB",      "glWindowPos2fARB",
      "glGenTexturesEXT",         "glIsTextureEXT",            "glDeleteTexturesEXT",
      "glAreTexturesResidentEXT", "glPrioritizeTexturesEXT"};
  for (unsigned i = 0; i < sizeof names / sizeof names[0]; i++)
    printf("%-28s %s\n", names[i], OSMesaGetProcAddress(names[i]) ? "found" : "NULL");

  PFNGLBLENDEQUATIONEXTPROC blend_equation =
      (PFNGLBLENDEQUATIONEXTPROC)OSMesaGetProcAddress("glBlendEquationEXT");
  PFNGLBINDTEXTUREEXTPROC bind_texture =
      (PFNGLBINDTEXTUREEXTPROC)OSMesaGetProcAddress("glBindTextureEXT");
  if (!blend_equation || !bind_texture) return 3;
  blend_equation(GL_MAX_EXT);
  GLint equation = 0, bound = 0;
  glGetIntegerv(GL_BLEND_EQUATION_EXT, &equation);
  bind_texture(GL_TEXTURE_2D, 5);
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
  printf("BLEND_EQUATION 0x%x  TEXTURE_BINDING_2D %d  err 0x%x\n", equation, bound,
         glGetError());
  OSMesaDestroyContext(ctx);
  free(buf);
  return 0;
}
