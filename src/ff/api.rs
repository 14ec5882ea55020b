//! The GL entry points the layer knows, as one table: each call's C name and its parameter
//! list as `GL/gl.h` declares it. The script reader dispatches on it and lists it in
//! "unknown call" errors, the script printer takes every call name from it, and the native
//! path names the call behind a GL error from it ([`Command::entry`]), so a name is spelled
//! once, here.

use std::fmt;

use super::combiners::CombinerParam;
use super::command::Command;
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
    Color3f = "glColor3f"(Form::Script, "GLfloat red, GLfloat green, GLfloat blue");
    Color4f = "glColor4f"(Form::Script, "GLfloat red, GLfloat green, GLfloat blue, GLfloat alpha");
    Normal3f = "glNormal3f"(Form::Script, "GLfloat nx, GLfloat ny, GLfloat nz");
    TexCoord1f = "glTexCoord1f"(Form::Script, "GLfloat s");
    TexCoord2f = "glTexCoord2f"(Form::Script, "GLfloat s, GLfloat t");
    TexCoord3f = "glTexCoord3f"(Form::Script, "GLfloat s, GLfloat t, GLfloat r");
    TexCoord4f = "glTexCoord4f"(Form::Script, "GLfloat s, GLfloat t, GLfloat r, GLfloat q");
    MultiTexCoord1f = "glMultiTexCoord1f"(Form::Script, "GLenum target, GLfloat s");
    MultiTexCoord2f = "glMultiTexCoord2f"(Form::Script, "GLenum target, GLfloat s, GLfloat t");
    MultiTexCoord3f = "glMultiTexCoord3f"(Form::Script, "GLenum target, GLfloat s, GLfloat t, GLfloat r");
    MultiTexCoord4f = "glMultiTexCoord4f"(Form::Script, "GLenum target, GLfloat s, GLfloat t, GLfloat r, GLfloat q");
    Vertex2f = "glVertex2f"(Form::Script, "GLfloat x, GLfloat y");
    Vertex3f = "glVertex3f"(Form::Script, "GLfloat x, GLfloat y, GLfloat z");
    Vertex4f = "glVertex4f"(Form::Script, "GLfloat x, GLfloat y, GLfloat z, GLfloat w");
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
