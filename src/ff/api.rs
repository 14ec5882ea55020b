//! The GL entry points the layer knows, as one table: each call's C name and its parameter
//! list as `GL/gl.h` declares it. The script reader dispatches on it and lists it in
//! "unknown call" errors, the script printer takes every call name from it, and the native
//! path names the call behind a GL error from it ([`Command::entry`]), so a name is spelled
//! once, here.

use std::fmt;

use super::combiners::CombinerParam;
use super::command::Command;
use super::fog::FogParam;
use super::light::{LightModelParam, LightParam, MaterialParam};
use super::texenv::TexEnvParam;
use super::texgen::TexGenParam;
use super::texture::TexParam;

/// Whether a script may spell the call. `Client` calls exist only as what a path issues
/// for a `Command::Draw` (a script draws with glBegin/glEnd).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Form {
    Script,
    Client,
}

macro_rules! entry_points {
    ($($variant:ident = $name:literal ($form:expr, $params:literal);)*) => {
        /// A GL entry point.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum Entry {
            $($variant,)*
        }

        impl Entry {
            /// Every entry point, in the table's order.
            pub const ALL: &'static [Entry] = &[$(Entry::$variant,)*];

            /// The C name (`glMatrixMode`).
            pub fn name(self) -> &'static str {
                match self {
                    $(Entry::$variant => $name,)*
                }
            }

            /// The parameter list as `GL/gl.h` declares it (empty for `void`).
            pub fn params(self) -> &'static str {
                match self {
                    $(Entry::$variant => $params,)*
                }
            }

            /// Whether a script may spell it.
            pub fn form(self) -> Form {
                match self {
                    $(Entry::$variant => $form,)*
                }
            }
        }
    };
}

entry_points! {
    MatrixMode = "glMatrixMode"(Form::Script, "GLenum mode");
    LoadIdentity = "glLoadIdentity"(Form::Script, "");
    LoadMatrixf = "glLoadMatrixf"(Form::Script, "const GLfloat *m");
    MultMatrixf = "glMultMatrixf"(Form::Script, "const GLfloat *m");
    PushMatrix = "glPushMatrix"(Form::Script, "");
    PopMatrix = "glPopMatrix"(Form::Script, "");
    Translatef = "glTranslatef"(Form::Script, "GLfloat x, GLfloat y, GLfloat z");
    Rotatef = "glRotatef"(Form::Script, "GLfloat angle, GLfloat x, GLfloat y, GLfloat z");
    Scalef = "glScalef"(Form::Script, "GLfloat x, GLfloat y, GLfloat z");
    Frustum = "glFrustum"(Form::Script, "GLdouble left, GLdouble right, GLdouble bottom, GLdouble top, GLdouble zNear, GLdouble zFar");
    Ortho = "glOrtho"(Form::Script, "GLdouble left, GLdouble right, GLdouble bottom, GLdouble top, GLdouble zNear, GLdouble zFar");
    Viewport = "glViewport"(Form::Script, "GLint x, GLint y, GLsizei width, GLsizei height");
    DepthRange = "glDepthRange"(Form::Script, "GLdouble zNear, GLdouble zFar");
    Enable = "glEnable"(Form::Script, "GLenum cap");
    Disable = "glDisable"(Form::Script, "GLenum cap");
    Vertex2s = "glVertex2s"(Form::Script, "GLshort x, GLshort y");
    Vertex2sv = "glVertex2sv"(Form::Script, "const GLshort *v");
    Vertex2i = "glVertex2i"(Form::Script, "GLint x, GLint y");
    Vertex2iv = "glVertex2iv"(Form::Script, "const GLint *v");
    Vertex2f = "glVertex2f"(Form::Script, "GLfloat x, GLfloat y");
    Vertex2fv = "glVertex2fv"(Form::Script, "const GLfloat *v");
    Vertex2d = "glVertex2d"(Form::Script, "GLdouble x, GLdouble y");
    Vertex2dv = "glVertex2dv"(Form::Script, "const GLdouble *v");
    Vertex3s = "glVertex3s"(Form::Script, "GLshort x, GLshort y, GLshort z");
    Vertex3sv = "glVertex3sv"(Form::Script, "const GLshort *v");
    Vertex3i = "glVertex3i"(Form::Script, "GLint x, GLint y, GLint z");
    Vertex3iv = "glVertex3iv"(Form::Script, "const GLint *v");
    Vertex3f = "glVertex3f"(Form::Script, "GLfloat x, GLfloat y, GLfloat z");
    Vertex3fv = "glVertex3fv"(Form::Script, "const GLfloat *v");
    Vertex3d = "glVertex3d"(Form::Script, "GLdouble x, GLdouble y, GLdouble z");
    Vertex3dv = "glVertex3dv"(Form::Script, "const GLdouble *v");
    Vertex4s = "glVertex4s"(Form::Script, "GLshort x, GLshort y, GLshort z, GLshort w");
    Vertex4sv = "glVertex4sv"(Form::Script, "const GLshort *v");
    Vertex4i = "glVertex4i"(Form::Script, "GLint x, GLint y, GLint z, GLint w");
    Vertex4iv = "glVertex4iv"(Form::Script, "const GLint *v");
    Vertex4f = "glVertex4f"(Form::Script, "GLfloat x, GLfloat y, GLfloat z, GLfloat w");
    Vertex4fv = "glVertex4fv"(Form::Script, "const GLfloat *v");
    Vertex4d = "glVertex4d"(Form::Script, "GLdouble x, GLdouble y, GLdouble z, GLdouble w");
    Vertex4dv = "glVertex4dv"(Form::Script, "const GLdouble *v");
    Color3b = "glColor3b"(Form::Script, "GLbyte red, GLbyte green, GLbyte blue");
    Color3bv = "glColor3bv"(Form::Script, "const GLbyte *v");
    Color3s = "glColor3s"(Form::Script, "GLshort red, GLshort green, GLshort blue");
    Color3sv = "glColor3sv"(Form::Script, "const GLshort *v");
    Color3i = "glColor3i"(Form::Script, "GLint red, GLint green, GLint blue");
    Color3iv = "glColor3iv"(Form::Script, "const GLint *v");
    Color3f = "glColor3f"(Form::Script, "GLfloat red, GLfloat green, GLfloat blue");
    Color3fv = "glColor3fv"(Form::Script, "const GLfloat *v");
    Color3d = "glColor3d"(Form::Script, "GLdouble red, GLdouble green, GLdouble blue");
    Color3dv = "glColor3dv"(Form::Script, "const GLdouble *v");
    Color3ub = "glColor3ub"(Form::Script, "GLubyte red, GLubyte green, GLubyte blue");
    Color3ubv = "glColor3ubv"(Form::Script, "const GLubyte *v");
    Color3us = "glColor3us"(Form::Script, "GLushort red, GLushort green, GLushort blue");
    Color3usv = "glColor3usv"(Form::Script, "const GLushort *v");
    Color3ui = "glColor3ui"(Form::Script, "GLuint red, GLuint green, GLuint blue");
    Color3uiv = "glColor3uiv"(Form::Script, "const GLuint *v");
    Color4b = "glColor4b"(Form::Script, "GLbyte red, GLbyte green, GLbyte blue, GLbyte alpha");
    Color4bv = "glColor4bv"(Form::Script, "const GLbyte *v");
    Color4s = "glColor4s"(Form::Script, "GLshort red, GLshort green, GLshort blue, GLshort alpha");
    Color4sv = "glColor4sv"(Form::Script, "const GLshort *v");
    Color4i = "glColor4i"(Form::Script, "GLint red, GLint green, GLint blue, GLint alpha");
    Color4iv = "glColor4iv"(Form::Script, "const GLint *v");
    Color4f = "glColor4f"(Form::Script, "GLfloat red, GLfloat green, GLfloat blue, GLfloat alpha");
    Color4fv = "glColor4fv"(Form::Script, "const GLfloat *v");
    Color4d = "glColor4d"(Form::Script, "GLdouble red, GLdouble green, GLdouble blue, GLdouble alpha");
    Color4dv = "glColor4dv"(Form::Script, "const GLdouble *v");
    Color4ub = "glColor4ub"(Form::Script, "GLubyte red, GLubyte green, GLubyte blue, GLubyte alpha");
    Color4ubv = "glColor4ubv"(Form::Script, "const GLubyte *v");
    Color4us = "glColor4us"(Form::Script, "GLushort red, GLushort green, GLushort blue, GLushort alpha");
    Color4usv = "glColor4usv"(Form::Script, "const GLushort *v");
    Color4ui = "glColor4ui"(Form::Script, "GLuint red, GLuint green, GLuint blue, GLuint alpha");
    Color4uiv = "glColor4uiv"(Form::Script, "const GLuint *v");
    Normal3b = "glNormal3b"(Form::Script, "GLbyte nx, GLbyte ny, GLbyte nz");
    Normal3bv = "glNormal3bv"(Form::Script, "const GLbyte *v");
    Normal3s = "glNormal3s"(Form::Script, "GLshort nx, GLshort ny, GLshort nz");
    Normal3sv = "glNormal3sv"(Form::Script, "const GLshort *v");
    Normal3i = "glNormal3i"(Form::Script, "GLint nx, GLint ny, GLint nz");
    Normal3iv = "glNormal3iv"(Form::Script, "const GLint *v");
    Normal3f = "glNormal3f"(Form::Script, "GLfloat nx, GLfloat ny, GLfloat nz");
    Normal3fv = "glNormal3fv"(Form::Script, "const GLfloat *v");
    Normal3d = "glNormal3d"(Form::Script, "GLdouble nx, GLdouble ny, GLdouble nz");
    Normal3dv = "glNormal3dv"(Form::Script, "const GLdouble *v");
    TexCoord1s = "glTexCoord1s"(Form::Script, "GLshort s");
    TexCoord1sv = "glTexCoord1sv"(Form::Script, "const GLshort *v");
    TexCoord1i = "glTexCoord1i"(Form::Script, "GLint s");
    TexCoord1iv = "glTexCoord1iv"(Form::Script, "const GLint *v");
    TexCoord1f = "glTexCoord1f"(Form::Script, "GLfloat s");
    TexCoord1fv = "glTexCoord1fv"(Form::Script, "const GLfloat *v");
    TexCoord1d = "glTexCoord1d"(Form::Script, "GLdouble s");
    TexCoord1dv = "glTexCoord1dv"(Form::Script, "const GLdouble *v");
    TexCoord2s = "glTexCoord2s"(Form::Script, "GLshort s, GLshort t");
    TexCoord2sv = "glTexCoord2sv"(Form::Script, "const GLshort *v");
    TexCoord2i = "glTexCoord2i"(Form::Script, "GLint s, GLint t");
    TexCoord2iv = "glTexCoord2iv"(Form::Script, "const GLint *v");
    TexCoord2f = "glTexCoord2f"(Form::Script, "GLfloat s, GLfloat t");
    TexCoord2fv = "glTexCoord2fv"(Form::Script, "const GLfloat *v");
    TexCoord2d = "glTexCoord2d"(Form::Script, "GLdouble s, GLdouble t");
    TexCoord2dv = "glTexCoord2dv"(Form::Script, "const GLdouble *v");
    TexCoord3s = "glTexCoord3s"(Form::Script, "GLshort s, GLshort t, GLshort r");
    TexCoord3sv = "glTexCoord3sv"(Form::Script, "const GLshort *v");
    TexCoord3i = "glTexCoord3i"(Form::Script, "GLint s, GLint t, GLint r");
    TexCoord3iv = "glTexCoord3iv"(Form::Script, "const GLint *v");
    TexCoord3f = "glTexCoord3f"(Form::Script, "GLfloat s, GLfloat t, GLfloat r");
    TexCoord3fv = "glTexCoord3fv"(Form::Script, "const GLfloat *v");
    TexCoord3d = "glTexCoord3d"(Form::Script, "GLdouble s, GLdouble t, GLdouble r");
    TexCoord3dv = "glTexCoord3dv"(Form::Script, "const GLdouble *v");
    TexCoord4s = "glTexCoord4s"(Form::Script, "GLshort s, GLshort t, GLshort r, GLshort q");
    TexCoord4sv = "glTexCoord4sv"(Form::Script, "const GLshort *v");
    TexCoord4i = "glTexCoord4i"(Form::Script, "GLint s, GLint t, GLint r, GLint q");
    TexCoord4iv = "glTexCoord4iv"(Form::Script, "const GLint *v");
    TexCoord4f = "glTexCoord4f"(Form::Script, "GLfloat s, GLfloat t, GLfloat r, GLfloat q");
    TexCoord4fv = "glTexCoord4fv"(Form::Script, "const GLfloat *v");
    TexCoord4d = "glTexCoord4d"(Form::Script, "GLdouble s, GLdouble t, GLdouble r, GLdouble q");
    TexCoord4dv = "glTexCoord4dv"(Form::Script, "const GLdouble *v");
    MultiTexCoord1s = "glMultiTexCoord1s"(Form::Script, "GLenum target, GLshort s");
    MultiTexCoord1sv = "glMultiTexCoord1sv"(Form::Script, "GLenum target, const GLshort *v");
    MultiTexCoord1i = "glMultiTexCoord1i"(Form::Script, "GLenum target, GLint s");
    MultiTexCoord1iv = "glMultiTexCoord1iv"(Form::Script, "GLenum target, const GLint *v");
    MultiTexCoord1f = "glMultiTexCoord1f"(Form::Script, "GLenum target, GLfloat s");
    MultiTexCoord1fv = "glMultiTexCoord1fv"(Form::Script, "GLenum target, const GLfloat *v");
    MultiTexCoord1d = "glMultiTexCoord1d"(Form::Script, "GLenum target, GLdouble s");
    MultiTexCoord1dv = "glMultiTexCoord1dv"(Form::Script, "GLenum target, const GLdouble *v");
    MultiTexCoord2s = "glMultiTexCoord2s"(Form::Script, "GLenum target, GLshort s, GLshort t");
    MultiTexCoord2sv = "glMultiTexCoord2sv"(Form::Script, "GLenum target, const GLshort *v");
    MultiTexCoord2i = "glMultiTexCoord2i"(Form::Script, "GLenum target, GLint s, GLint t");
    MultiTexCoord2iv = "glMultiTexCoord2iv"(Form::Script, "GLenum target, const GLint *v");
    MultiTexCoord2f = "glMultiTexCoord2f"(Form::Script, "GLenum target, GLfloat s, GLfloat t");
    MultiTexCoord2fv = "glMultiTexCoord2fv"(Form::Script, "GLenum target, const GLfloat *v");
    MultiTexCoord2d = "glMultiTexCoord2d"(Form::Script, "GLenum target, GLdouble s, GLdouble t");
    MultiTexCoord2dv = "glMultiTexCoord2dv"(Form::Script, "GLenum target, const GLdouble *v");
    MultiTexCoord3s = "glMultiTexCoord3s"(Form::Script, "GLenum target, GLshort s, GLshort t, GLshort r");
    MultiTexCoord3sv = "glMultiTexCoord3sv"(Form::Script, "GLenum target, const GLshort *v");
    MultiTexCoord3i = "glMultiTexCoord3i"(Form::Script, "GLenum target, GLint s, GLint t, GLint r");
    MultiTexCoord3iv = "glMultiTexCoord3iv"(Form::Script, "GLenum target, const GLint *v");
    MultiTexCoord3f = "glMultiTexCoord3f"(Form::Script, "GLenum target, GLfloat s, GLfloat t, GLfloat r");
    MultiTexCoord3fv = "glMultiTexCoord3fv"(Form::Script, "GLenum target, const GLfloat *v");
    MultiTexCoord3d = "glMultiTexCoord3d"(Form::Script, "GLenum target, GLdouble s, GLdouble t, GLdouble r");
    MultiTexCoord3dv = "glMultiTexCoord3dv"(Form::Script, "GLenum target, const GLdouble *v");
    MultiTexCoord4s = "glMultiTexCoord4s"(Form::Script, "GLenum target, GLshort s, GLshort t, GLshort r, GLshort q");
    MultiTexCoord4sv = "glMultiTexCoord4sv"(Form::Script, "GLenum target, const GLshort *v");
    MultiTexCoord4i = "glMultiTexCoord4i"(Form::Script, "GLenum target, GLint s, GLint t, GLint r, GLint q");
    MultiTexCoord4iv = "glMultiTexCoord4iv"(Form::Script, "GLenum target, const GLint *v");
    MultiTexCoord4f = "glMultiTexCoord4f"(Form::Script, "GLenum target, GLfloat s, GLfloat t, GLfloat r, GLfloat q");
    MultiTexCoord4fv = "glMultiTexCoord4fv"(Form::Script, "GLenum target, const GLfloat *v");
    MultiTexCoord4d = "glMultiTexCoord4d"(Form::Script, "GLenum target, GLdouble s, GLdouble t, GLdouble r, GLdouble q");
    MultiTexCoord4dv = "glMultiTexCoord4dv"(Form::Script, "GLenum target, const GLdouble *v");
    MultiTexCoord1sARB = "glMultiTexCoord1sARB"(Form::Script, "GLenum target, GLshort s");
    MultiTexCoord1svARB = "glMultiTexCoord1svARB"(Form::Script, "GLenum target, const GLshort *v");
    MultiTexCoord1iARB = "glMultiTexCoord1iARB"(Form::Script, "GLenum target, GLint s");
    MultiTexCoord1ivARB = "glMultiTexCoord1ivARB"(Form::Script, "GLenum target, const GLint *v");
    MultiTexCoord1fARB = "glMultiTexCoord1fARB"(Form::Script, "GLenum target, GLfloat s");
    MultiTexCoord1fvARB = "glMultiTexCoord1fvARB"(Form::Script, "GLenum target, const GLfloat *v");
    MultiTexCoord1dARB = "glMultiTexCoord1dARB"(Form::Script, "GLenum target, GLdouble s");
    MultiTexCoord1dvARB = "glMultiTexCoord1dvARB"(Form::Script, "GLenum target, const GLdouble *v");
    MultiTexCoord2sARB = "glMultiTexCoord2sARB"(Form::Script, "GLenum target, GLshort s, GLshort t");
    MultiTexCoord2svARB = "glMultiTexCoord2svARB"(Form::Script, "GLenum target, const GLshort *v");
    MultiTexCoord2iARB = "glMultiTexCoord2iARB"(Form::Script, "GLenum target, GLint s, GLint t");
    MultiTexCoord2ivARB = "glMultiTexCoord2ivARB"(Form::Script, "GLenum target, const GLint *v");
    MultiTexCoord2fARB = "glMultiTexCoord2fARB"(Form::Script, "GLenum target, GLfloat s, GLfloat t");
    MultiTexCoord2fvARB = "glMultiTexCoord2fvARB"(Form::Script, "GLenum target, const GLfloat *v");
    MultiTexCoord2dARB = "glMultiTexCoord2dARB"(Form::Script, "GLenum target, GLdouble s, GLdouble t");
    MultiTexCoord2dvARB = "glMultiTexCoord2dvARB"(Form::Script, "GLenum target, const GLdouble *v");
    MultiTexCoord3sARB = "glMultiTexCoord3sARB"(Form::Script, "GLenum target, GLshort s, GLshort t, GLshort r");
    MultiTexCoord3svARB = "glMultiTexCoord3svARB"(Form::Script, "GLenum target, const GLshort *v");
    MultiTexCoord3iARB = "glMultiTexCoord3iARB"(Form::Script, "GLenum target, GLint s, GLint t, GLint r");
    MultiTexCoord3ivARB = "glMultiTexCoord3ivARB"(Form::Script, "GLenum target, const GLint *v");
    MultiTexCoord3fARB = "glMultiTexCoord3fARB"(Form::Script, "GLenum target, GLfloat s, GLfloat t, GLfloat r");
    MultiTexCoord3fvARB = "glMultiTexCoord3fvARB"(Form::Script, "GLenum target, const GLfloat *v");
    MultiTexCoord3dARB = "glMultiTexCoord3dARB"(Form::Script, "GLenum target, GLdouble s, GLdouble t, GLdouble r");
    MultiTexCoord3dvARB = "glMultiTexCoord3dvARB"(Form::Script, "GLenum target, const GLdouble *v");
    MultiTexCoord4sARB = "glMultiTexCoord4sARB"(Form::Script, "GLenum target, GLshort s, GLshort t, GLshort r, GLshort q");
    MultiTexCoord4svARB = "glMultiTexCoord4svARB"(Form::Script, "GLenum target, const GLshort *v");
    MultiTexCoord4iARB = "glMultiTexCoord4iARB"(Form::Script, "GLenum target, GLint s, GLint t, GLint r, GLint q");
    MultiTexCoord4ivARB = "glMultiTexCoord4ivARB"(Form::Script, "GLenum target, const GLint *v");
    MultiTexCoord4fARB = "glMultiTexCoord4fARB"(Form::Script, "GLenum target, GLfloat s, GLfloat t, GLfloat r, GLfloat q");
    MultiTexCoord4fvARB = "glMultiTexCoord4fvARB"(Form::Script, "GLenum target, const GLfloat *v");
    MultiTexCoord4dARB = "glMultiTexCoord4dARB"(Form::Script, "GLenum target, GLdouble s, GLdouble t, GLdouble r, GLdouble q");
    MultiTexCoord4dvARB = "glMultiTexCoord4dvARB"(Form::Script, "GLenum target, const GLdouble *v");
    ActiveTextureARB = "glActiveTextureARB"(Form::Script, "GLenum texture");
    Rects = "glRects"(Form::Script, "GLshort x1, GLshort y1, GLshort x2, GLshort y2");
    Rectsv = "glRectsv"(Form::Script, "const GLshort *v1, const GLshort *v2");
    Recti = "glRecti"(Form::Script, "GLint x1, GLint y1, GLint x2, GLint y2");
    Rectiv = "glRectiv"(Form::Script, "const GLint *v1, const GLint *v2");
    Rectf = "glRectf"(Form::Script, "GLfloat x1, GLfloat y1, GLfloat x2, GLfloat y2");
    Rectfv = "glRectfv"(Form::Script, "const GLfloat *v1, const GLfloat *v2");
    Rectd = "glRectd"(Form::Script, "GLdouble x1, GLdouble y1, GLdouble x2, GLdouble y2");
    Rectdv = "glRectdv"(Form::Script, "const GLdouble *v1, const GLdouble *v2");
    Translated = "glTranslated"(Form::Script, "GLdouble x, GLdouble y, GLdouble z");
    Rotated = "glRotated"(Form::Script, "GLdouble angle, GLdouble x, GLdouble y, GLdouble z");
    Scaled = "glScaled"(Form::Script, "GLdouble x, GLdouble y, GLdouble z");
    LoadMatrixd = "glLoadMatrixd"(Form::Script, "const GLdouble *m");
    MultMatrixd = "glMultMatrixd"(Form::Script, "const GLdouble *m");
    TexGenf = "glTexGenf"(Form::Script, "GLenum coord, GLenum pname, GLfloat param");
    TexGend = "glTexGend"(Form::Script, "GLenum coord, GLenum pname, GLdouble param");
    TexGendv = "glTexGendv"(Form::Script, "GLenum coord, GLenum pname, const GLdouble *params");
    TexGeniv = "glTexGeniv"(Form::Script, "GLenum coord, GLenum pname, const GLint *params");
    Begin = "glBegin"(Form::Script, "GLenum mode");
    End = "glEnd"(Form::Script, "");
    Lightf = "glLightf"(Form::Script, "GLenum light, GLenum pname, GLfloat param");
    Lighti = "glLighti"(Form::Script, "GLenum light, GLenum pname, GLint param");
    Lightfv = "glLightfv"(Form::Script, "GLenum light, GLenum pname, const GLfloat *params");
    LightModelf = "glLightModelf"(Form::Script, "GLenum pname, GLfloat param");
    LightModeli = "glLightModeli"(Form::Script, "GLenum pname, GLint param");
    LightModelfv = "glLightModelfv"(Form::Script, "GLenum pname, const GLfloat *params");
    Materialf = "glMaterialf"(Form::Script, "GLenum face, GLenum pname, GLfloat param");
    Materialfv = "glMaterialfv"(Form::Script, "GLenum face, GLenum pname, const GLfloat *params");
    ColorMaterial = "glColorMaterial"(Form::Script, "GLenum face, GLenum mode");
    ShadeModel = "glShadeModel"(Form::Script, "GLenum mode");
    ActiveTexture = "glActiveTexture"(Form::Script, "GLenum texture");
    BindTexture = "glBindTexture"(Form::Script, "GLenum target, GLuint texture");
    TexImage1D = "glTexImage1D"(Form::Script, "GLenum target, GLint level, GLint internalformat, GLsizei width, GLint border, GLenum format, GLenum type, const void *pixels");
    TexImage2D = "glTexImage2D"(Form::Script, "GLenum target, GLint level, GLint internalformat, GLsizei width, GLsizei height, GLint border, GLenum format, GLenum type, const void *pixels");
    TexSubImage2D = "glTexSubImage2D"(Form::Script, "GLenum target, GLint level, GLint xoffset, GLint yoffset, GLsizei width, GLsizei height, GLenum format, GLenum type, const void *pixels");
    CopyTexImage2D = "glCopyTexImage2D"(Form::Script, "GLenum target, GLint level, GLenum internalformat, GLint x, GLint y, GLsizei width, GLsizei height, GLint border");
    TexParameteri = "glTexParameteri"(Form::Script, "GLenum target, GLenum pname, GLint param");
    TexParameterf = "glTexParameterf"(Form::Script, "GLenum target, GLenum pname, GLfloat param");
    TexParameterfv = "glTexParameterfv"(Form::Script, "GLenum target, GLenum pname, const GLfloat *params");
    TexGeni = "glTexGeni"(Form::Script, "GLenum coord, GLenum pname, GLint param");
    TexGenfv = "glTexGenfv"(Form::Script, "GLenum coord, GLenum pname, const GLfloat *params");
    TexEnvi = "glTexEnvi"(Form::Script, "GLenum target, GLenum pname, GLint param");
    TexEnvf = "glTexEnvf"(Form::Script, "GLenum target, GLenum pname, GLfloat param");
    TexEnvfv = "glTexEnvfv"(Form::Script, "GLenum target, GLenum pname, const GLfloat *params");
    CombinerParameteriNV = "glCombinerParameteriNV"(Form::Script, "GLenum pname, GLint param");
    CombinerParameterfvNV = "glCombinerParameterfvNV"(Form::Script, "GLenum pname, const GLfloat *params");
    CombinerInputNV = "glCombinerInputNV"(Form::Script, "GLenum stage, GLenum portion, GLenum variable, GLenum input, GLenum mapping, GLenum componentUsage");
    CombinerOutputNV = "glCombinerOutputNV"(Form::Script, "GLenum stage, GLenum portion, GLenum abOutput, GLenum cdOutput, GLenum sumOutput, GLenum scale, GLenum bias, GLboolean abDotProduct, GLboolean cdDotProduct, GLboolean muxSum");
    FinalCombinerInputNV = "glFinalCombinerInputNV"(Form::Script, "GLenum variable, GLenum input, GLenum mapping, GLenum componentUsage");
    AlphaFunc = "glAlphaFunc"(Form::Script, "GLenum func, GLfloat ref");
    DepthFunc = "glDepthFunc"(Form::Script, "GLenum func");
    DepthMask = "glDepthMask"(Form::Script, "GLboolean flag");
    StencilFunc = "glStencilFunc"(Form::Script, "GLenum func, GLint ref, GLuint mask");
    StencilOp = "glStencilOp"(Form::Script, "GLenum fail, GLenum zfail, GLenum zpass");
    StencilMask = "glStencilMask"(Form::Script, "GLuint mask");
    BlendFunc = "glBlendFunc"(Form::Script, "GLenum sfactor, GLenum dfactor");
    ColorMask = "glColorMask"(Form::Script, "GLboolean red, GLboolean green, GLboolean blue, GLboolean alpha");
    PolygonOffset = "glPolygonOffset"(Form::Script, "GLfloat factor, GLfloat units");
    PolygonMode = "glPolygonMode"(Form::Script, "GLenum face, GLenum mode");
    CullFace = "glCullFace"(Form::Script, "GLenum mode");
    FrontFace = "glFrontFace"(Form::Script, "GLenum mode");
    LineWidth = "glLineWidth"(Form::Script, "GLfloat width");
    PointSize = "glPointSize"(Form::Script, "GLfloat size");
    Clear = "glClear"(Form::Script, "GLbitfield mask");
    ClearColor = "glClearColor"(Form::Script, "GLfloat red, GLfloat green, GLfloat blue, GLfloat alpha");
    ClearDepth = "glClearDepth"(Form::Script, "GLdouble depth");
    ClearStencil = "glClearStencil"(Form::Script, "GLint s");
    ReadPixels = "glReadPixels"(Form::Script, "GLint x, GLint y, GLsizei width, GLsizei height, GLenum format, GLenum type, void *pixels");
    DrawArrays = "glDrawArrays"(Form::Client, "GLenum mode, GLint first, GLsizei count");
    DrawElements = "glDrawElements"(Form::Client, "GLenum mode, GLsizei count, GLenum type, const void *indices");
    // Fog, scissor, clip planes, logic op, blending (GL 1.0–1.4).
    Fogf = "glFogf"(Form::Script, "GLenum pname, GLfloat param");
    Fogi = "glFogi"(Form::Script, "GLenum pname, GLint param");
    Fogfv = "glFogfv"(Form::Script, "GLenum pname, const GLfloat *params");
    Fogiv = "glFogiv"(Form::Script, "GLenum pname, const GLint *params");
    Scissor = "glScissor"(Form::Script, "GLint x, GLint y, GLsizei width, GLsizei height");
    ClipPlane = "glClipPlane"(Form::Script, "GLenum plane, const GLdouble *equation");
    LogicOp = "glLogicOp"(Form::Script, "GLenum opcode");
    BlendColor = "glBlendColor"(Form::Script, "GLfloat red, GLfloat green, GLfloat blue, GLfloat alpha");
    BlendEquation = "glBlendEquation"(Form::Script, "GLenum mode");
    BlendFuncSeparate = "glBlendFuncSeparate"(Form::Script, "GLenum sfactorRGB, GLenum dfactorRGB, GLenum sfactorAlpha, GLenum dfactorAlpha");
    Hint = "glHint"(Form::Script, "GLenum target, GLenum mode");

}

impl Entry {
    /// The entry point a C name means.
    pub fn from_name(name: &str) -> Option<Entry> {
        Entry::ALL.iter().copied().find(|e| e.name() == name)
    }

    /// Every call a script may spell, for errors and generators.
    pub fn script_names() -> Vec<&'static str> {
        Entry::ALL
            .iter()
            .filter(|e| e.form() == Form::Script)
            .map(|e| e.name())
            .collect()
    }

    /// The number of parameters.
    pub fn arity(self) -> usize {
        match self.params() {
            "" => 0,
            p => p.split(',').count(),
        }
    }

    /// The C prototype, `void glMatrixMode(GLenum mode)`.
    pub fn prototype(self) -> String {
        let params = match self.params() {
            "" => "void",
            p => p,
        };
        format!("void {}({params})", self.name())
    }
}

/// The vertex-attribute families, whose variants differ only in how they read their values
/// (`glColor3ub`, `glVertex2iv`, `glMultiTexCoord2fARB`, `glRectd`…).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Attrib {
    Vertex,
    Color,
    Normal,
    TexCoord,
    /// The texture unit comes first (`GLenum target`).
    MultiTexCoord,
    /// glRect: two corners, drawn as one GL_QUADS (as Mesa draws it).
    Rect,
}

/// A C parameter type of those families.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CType {
    Byte,
    UByte,
    Short,
    UShort,
    Int,
    UInt,
    Float,
    Double,
}

impl CType {
    /// The type suffix of an entry-point name (`ub`, `s`, `d`…).
    fn from_suffix(s: &str) -> Option<CType> {
        Some(match s {
            "b" => CType::Byte,
            "ub" => CType::UByte,
            "s" => CType::Short,
            "us" => CType::UShort,
            "i" => CType::Int,
            "ui" => CType::UInt,
            "f" => CType::Float,
            "d" => CType::Double,
            _ => return None,
        })
    }

    /// The C conversion of an argument to this parameter type: an integer type truncates
    /// towards zero and wraps modulo 2ⁿ (C11 6.3.1.4 and 6.3.1.3, as gcc does); GLfloat
    /// rounds to f32; a non-finite value given to an integer type becomes 0 (undefined in
    /// C; gcc on x86-64 gives the "integer indefinite", which wraps to 0 for the narrow
    /// types).
    pub fn convert(self, v: f64) -> f64 {
        let wrap = |bits: u32, signed: bool| -> f64 {
            if !v.is_finite() {
                return 0.0;
            }
            let t = v.trunc();
            let m = 2f64.powi(bits as i32);
            let mut r = t.rem_euclid(m);
            if signed && r >= m / 2.0 {
                r -= m;
            }
            r
        };
        match self {
            CType::Byte => wrap(8, true),
            CType::UByte => wrap(8, false),
            CType::Short => wrap(16, true),
            CType::UShort => wrap(16, false),
            CType::Int => wrap(32, true),
            CType::UInt => wrap(32, false),
            CType::Float => f64::from(v as f32),
            CType::Double => v,
        }
    }

    /// A colour or normal component from this type (GL 1.5 Table 2.9, Mesa's
    /// BYTE_TO_FLOAT…): unsigned c/(2ⁿ − 1); signed (2c + 1)/(2ⁿ − 1); floats as they are.
    pub fn normalized(self, c: f64) -> f32 {
        let (bits, signed) = match self {
            CType::Byte => (8, true),
            CType::UByte => (8, false),
            CType::Short => (16, true),
            CType::UShort => (16, false),
            CType::Int => (32, true),
            CType::UInt => (32, false),
            CType::Float | CType::Double => return c as f32,
        };
        let max = 2f64.powi(bits) - 1.0;
        (if signed {
            (2.0 * c + 1.0) / max
        } else {
            c / max
        }) as f32
    }
}

/// How one variant of an [`Attrib`] family reads its values.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct AttribCall {
    pub attrib: Attrib,
    /// Components given (glRect: 4, the two corners).
    pub count: usize,
    pub ty: CType,
    /// The `…v` form: one array (two for glRect) instead of scalars.
    pub vector: bool,
}

impl Entry {
    /// The family variant this entry point is, read from its name.
    pub fn attrib_call(self) -> Option<AttribCall> {
        let name = self.name().strip_prefix("gl")?;
        let name = name.strip_suffix("ARB").unwrap_or(name);
        let (attrib, rest) = [
            ("MultiTexCoord", Attrib::MultiTexCoord),
            ("TexCoord", Attrib::TexCoord),
            ("Vertex", Attrib::Vertex),
            ("Color", Attrib::Color),
            ("Normal", Attrib::Normal),
            ("Rect", Attrib::Rect),
        ]
        .iter()
        .find_map(|(prefix, a)| name.strip_prefix(prefix).map(|r| (*a, r)))?;
        let (count, rest) = match attrib {
            Attrib::Rect => (4, rest),
            _ => {
                let digit = rest.chars().next()?.to_digit(10)? as usize;
                (digit, &rest[1..])
            }
        };
        let (ty, vector) = match rest.strip_suffix('v') {
            Some(t) => (CType::from_suffix(t)?, true),
            None => (CType::from_suffix(rest)?, false),
        };
        Some(AttribCall {
            attrib,
            count,
            ty,
            vector,
        })
    }
}

impl fmt::Display for Entry {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl Command {
    /// The entry point a program of the era called for this command (the one the script
    /// printer writes; a draw is glDrawElements or glDrawArrays, as the native path issues
    /// it).
    pub fn entry(&self) -> Entry {
        match self {
            Command::MatrixMode(_) => Entry::MatrixMode,
            Command::LoadIdentity => Entry::LoadIdentity,
            Command::LoadMatrix(_) => Entry::LoadMatrixf,
            Command::MultMatrix(_) => Entry::MultMatrixf,
            Command::PushMatrix => Entry::PushMatrix,
            Command::PopMatrix => Entry::PopMatrix,
            Command::Translate(_) => Entry::Translatef,
            Command::Rotate { .. } => Entry::Rotatef,
            Command::Scale(_) => Entry::Scalef,
            Command::Frustum(_) => Entry::Frustum,
            Command::Ortho(_) => Entry::Ortho,
            Command::Viewport(_) => Entry::Viewport,
            Command::DepthRange { .. } => Entry::DepthRange,
            Command::Enable(_) => Entry::Enable,
            Command::Disable(_) => Entry::Disable,
            Command::Color(_) => Entry::Color4f,
            Command::Normal(_) => Entry::Normal3f,
            Command::TexCoord { .. } => Entry::MultiTexCoord4f,
            Command::Light { param, .. } => match param {
                LightParam::SpotExponent(_)
                | LightParam::SpotCutoff(_)
                | LightParam::ConstantAttenuation(_)
                | LightParam::LinearAttenuation(_)
                | LightParam::QuadraticAttenuation(_) => Entry::Lightf,
                _ => Entry::Lightfv,
            },
            Command::LightModel(p) => match p {
                LightModelParam::Ambient(_) => Entry::LightModelfv,
                _ => Entry::LightModeli,
            },
            Command::Material { param, .. } => match param {
                MaterialParam::Shininess(_) => Entry::Materialf,
                _ => Entry::Materialfv,
            },
            Command::ColorMaterial { .. } => Entry::ColorMaterial,
            Command::ShadeModel(_) => Entry::ShadeModel,
            Command::ActiveTexture(_) => Entry::ActiveTexture,
            Command::BindTexture { .. } => Entry::BindTexture,
            Command::TexImage(t) => match t.target {
                super::texture::TextureTarget::Texture1D => Entry::TexImage1D,
                super::texture::TextureTarget::Texture2D => Entry::TexImage2D,
            },
            Command::TexSubImage2D(_) => Entry::TexSubImage2D,
            Command::CopyTexImage2D(_) => Entry::CopyTexImage2D,
            Command::TexParameter { param, .. } => match param {
                TexParam::BorderColor(_) => Entry::TexParameterfv,
                TexParam::CompareFailValue(_) => Entry::TexParameterf,
                _ => Entry::TexParameteri,
            },
            Command::TexGen { param, .. } => match param {
                TexGenParam::Mode(_) => Entry::TexGeni,
                _ => Entry::TexGenfv,
            },
            Command::TexEnv(p) => match p {
                TexEnvParam::Color(_) => Entry::TexEnvfv,
                TexEnvParam::RgbScale(_) | TexEnvParam::AlphaScale(_) => Entry::TexEnvf,
                _ => Entry::TexEnvi,
            },
            Command::CombinerParameter(p) => match p {
                CombinerParam::ConstantColor0(_) | CombinerParam::ConstantColor1(_) => {
                    Entry::CombinerParameterfvNV
                }
                _ => Entry::CombinerParameteriNV,
            },
            Command::CombinerInput { .. } => Entry::CombinerInputNV,
            Command::CombinerOutput { .. } => Entry::CombinerOutputNV,
            Command::FinalCombinerInput { .. } => Entry::FinalCombinerInputNV,
            Command::AlphaFunc { .. } => Entry::AlphaFunc,
            Command::DepthFunc(_) => Entry::DepthFunc,
            Command::DepthMask(_) => Entry::DepthMask,
            Command::StencilFunc { .. } => Entry::StencilFunc,
            Command::StencilOp { .. } => Entry::StencilOp,
            Command::StencilMask(_) => Entry::StencilMask,
            Command::BlendFunc { .. } => Entry::BlendFunc,
            Command::ColorMask(_) => Entry::ColorMask,
            Command::PolygonOffset { .. } => Entry::PolygonOffset,
            Command::PolygonMode { .. } => Entry::PolygonMode,
            Command::CullFace(_) => Entry::CullFace,
            Command::FrontFace(_) => Entry::FrontFace,
            Command::LineWidth(_) => Entry::LineWidth,
            Command::PointSize(_) => Entry::PointSize,
            Command::Scissor(_) => Entry::Scissor,
            Command::LogicOp(_) => Entry::LogicOp,
            Command::Hint { .. } => Entry::Hint,
            Command::BlendFuncSeparate { .. } => Entry::BlendFuncSeparate,
            Command::BlendEquation(_) => Entry::BlendEquation,
            Command::BlendColor(_) => Entry::BlendColor,
            Command::ClipPlane { .. } => Entry::ClipPlane,
            Command::Fog(p) => match p {
                FogParam::Mode(_) => Entry::Fogi,
                FogParam::Color(_) => Entry::Fogfv,
                _ => Entry::Fogf,
            },
            Command::Clear(_) => Entry::Clear,
            Command::ClearColor(_) => Entry::ClearColor,
            Command::ClearDepth(_) => Entry::ClearDepth,
            Command::ClearStencil(_) => Entry::ClearStencil,
            Command::ReadPixels(_) => Entry::ReadPixels,
            Command::Draw(g) => match g.indices {
                Some(_) => Entry::DrawElements,
                None => Entry::DrawArrays,
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_unique_and_round_trip() {
        for e in Entry::ALL {
            assert_eq!(Entry::from_name(e.name()), Some(*e));
        }
        let mut names: Vec<_> = Entry::ALL.iter().map(|e| e.name()).collect();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), Entry::ALL.len());
    }

    #[test]
    fn families_read_their_variant_from_the_name() {
        let c = Entry::Color3ub.attrib_call().unwrap();
        assert_eq!(
            (c.attrib, c.count, c.ty, c.vector),
            (Attrib::Color, 3, CType::UByte, false)
        );
        let m = Entry::MultiTexCoord2fvARB.attrib_call().unwrap();
        assert_eq!(
            (m.attrib, m.count, m.ty, m.vector),
            (Attrib::MultiTexCoord, 2, CType::Float, true)
        );
        let r = Entry::Rectdv.attrib_call().unwrap();
        assert_eq!((r.attrib, r.count, r.vector), (Attrib::Rect, 4, true));
        assert_eq!(Entry::LoadIdentity.attrib_call(), None);
        assert_eq!(Entry::Translated.attrib_call(), None);
        // Every family entry of the table parses.
        for e in Entry::ALL {
            let n = e.name();
            let family = n.starts_with("glRect")
                || [
                    "glVertex",
                    "glColor",
                    "glNormal",
                    "glTexCoord",
                    "glMultiTexCoord",
                ]
                .iter()
                .any(|p| {
                    n.strip_prefix(p)
                        .is_some_and(|r| r.starts_with(['1', '2', '3', '4']))
                });
            assert_eq!(e.attrib_call().is_some(), family, "{n}");
        }
    }

    #[test]
    fn c_conversions_and_gl_normalisation() {
        assert_eq!(CType::UByte.convert(256.0), 0.0);
        assert_eq!(CType::Byte.convert(200.0), -56.0);
        assert_eq!(CType::Int.convert(-2.7), -2.0);
        assert_eq!(CType::UByte.normalized(255.0), 1.0);
        assert_eq!(CType::Byte.normalized(127.0), 1.0);
        assert_eq!(CType::Byte.normalized(-128.0), -1.0);
        assert_eq!(CType::Short.normalized(0.0), (1.0 / 65535.0) as f32);
    }

    #[test]
    fn prototypes_read_like_gl_h() {
        assert_eq!(Entry::LoadIdentity.prototype(), "void glLoadIdentity(void)");
        assert_eq!(
            Entry::AlphaFunc.prototype(),
            "void glAlphaFunc(GLenum func, GLfloat ref)"
        );
        assert_eq!(Entry::TexImage2D.arity(), 9);
        assert!(!Entry::script_names().contains(&"glDrawArrays"));
    }
}
