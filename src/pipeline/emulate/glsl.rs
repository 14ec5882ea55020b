//! A GLSL source writer that records every uniform as it declares it, so that uploading
//! walks the same list the generator wrote — the two cannot drift apart.

use std::fmt::Write;

/// The GLSL type of a uniform.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum UniformType {
    Float,
    Vec2,
    Vec3,
    Vec4,
    Mat3,
    Mat4,
    Int,
    Sampler1D,
    Sampler2D,
    Sampler2DShadow,
    Sampler1DShadow,
}

impl UniformType {
    pub fn glsl(self) -> &'static str {
        match self {
            UniformType::Float => "float",
            UniformType::Vec2 => "vec2",
            UniformType::Vec3 => "vec3",
            UniformType::Vec4 => "vec4",
            UniformType::Mat3 => "mat3",
            UniformType::Mat4 => "mat4",
            UniformType::Int => "int",
            UniformType::Sampler1D => "sampler1D",
            UniformType::Sampler2D => "sampler2D",
            UniformType::Sampler2DShadow => "sampler2DShadow",
            UniformType::Sampler1DShadow => "sampler1DShadow",
        }
    }
}

/// One declared uniform.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UniformDecl {
    pub name: String,
    pub ty: UniformType,
}

/// Builds one shader's source: declarations first, then `main`'s body.
#[derive(Default, Debug)]
pub struct GlslWriter {
    declarations: String,
    body: String,
    uniforms: Vec<UniformDecl>,
}

impl GlslWriter {
    pub fn new() -> Self {
        Self::default()
    }

    /// Declares `uniform TY NAME;` once and returns the name.
    pub fn uniform(&mut self, name: &str, ty: UniformType) -> String {
        if !self.uniforms.iter().any(|u| u.name == name) {
            let _ = writeln!(self.declarations, "uniform {} {name};", ty.glsl());
            self.uniforms.push(UniformDecl {
                name: name.to_string(),
                ty,
            });
        }
        name.to_string()
    }

    /// Declares anything else (inputs, outputs, helper functions) verbatim.
    pub fn declare(&mut self, line: &str) {
        if !self.declarations.contains(line) {
            self.declarations.push_str(line);
            self.declarations.push('\n');
        }
    }

    /// Appends one statement (or comment) to `main`.
    pub fn line(&mut self, statement: &str) {
        self.body.push_str("    ");
        self.body.push_str(statement);
        self.body.push('\n');
    }

    pub fn uniforms(&self) -> &[UniformDecl] {
        &self.uniforms
    }

    /// The complete source, `#version 330 core` first.
    pub fn finish(&self) -> String {
        format!(
            "#version 330 core\n{}\nvoid main() {{\n{}}}\n",
            self.declarations, self.body
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uniforms_are_declared_once_and_recorded_in_order() {
        let mut w = GlslWriter::new();
        let a = w.uniform("alpha_ref", UniformType::Float);
        w.uniform("mvp", UniformType::Mat4);
        w.uniform("alpha_ref", UniformType::Float);
        w.line(&format!("if (color.a <= {a}) discard;"));
        let src = w.finish();
        assert_eq!(src.matches("uniform float alpha_ref;").count(), 1);
        assert!(src.starts_with("#version 330 core\n"));
        let names: Vec<_> = w.uniforms().iter().map(|u| u.name.as_str()).collect();
        assert_eq!(names, ["alpha_ref", "mvp"]);
    }
}
