//! A GLSL source writer that records every uniform as it declares it (by its
//! `UniformSource`), so that uploading walks the same list the generator wrote — the two
//! cannot drift apart. It uses `uniforms` (the sources and their types), never the reverse.

use std::fmt::Write;

use super::uniforms::UniformSource;

/// Builds one shader's source: declarations first, then `main`'s body.
#[derive(Default, Debug)]
pub struct GlslWriter {
    /// `#extension` directives, which GLSL wants before any other token.
    extensions: String,
    declarations: String,
    body: String,
    uniforms: Vec<UniformSource>,
}

impl GlslWriter {
    pub fn new() -> Self {
        Self::default()
    }

    /// Declares the uniform for `source` once and returns its name.
    pub fn uniform(&mut self, source: UniformSource) -> String {
        self.uniform_typed(source, source.ty().glsl())
    }

    /// Declares a uniform with an explicit GLSL type (samplers).
    pub fn uniform_typed(&mut self, source: UniformSource, glsl_type: &str) -> String {
        let name = source.name();
        if !self.uniforms.contains(&source) {
            let _ = writeln!(self.declarations, "uniform {glsl_type} {name};");
            self.uniforms.push(source);
        }
        name
    }

    /// Declares anything else (inputs, outputs, helper functions) once, verbatim.
    pub fn declare(&mut self, text: &str) {
        if !self.declarations.contains(text) {
            self.declarations.push_str(text);
            self.declarations.push('\n');
        }
    }

    /// Appends one statement (or comment) to `main`.
    pub fn line(&mut self, statement: impl AsRef<str>) {
        self.body.push_str("    ");
        self.body.push_str(statement.as_ref());
        self.body.push('\n');
    }

    pub fn uniforms(&self) -> &[UniformSource] {
        &self.uniforms
    }

    /// Requires a GLSL extension (`#extension NAME : require`), once.
    pub fn extension(&mut self, name: &str) {
        let line = format!("#extension {name} : require\n");
        if !self.extensions.contains(&line) {
            self.extensions.push_str(&line);
        }
    }

    /// The complete source, `#version 330 core` first, then the extensions.
    pub fn finish(&self) -> String {
        format!(
            "#version 330 core\n{}{}\nvoid main() {{\n{}}}\n",
            self.extensions, self.declarations, self.body
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uniforms_are_declared_once_and_recorded_in_order() {
        let mut w = GlslWriter::new();
        let a = w.uniform(UniformSource::AlphaRef);
        w.uniform(UniformSource::Modelview);
        w.uniform(UniformSource::AlphaRef);
        w.line(format!("if (color.a <= {a}) discard;"));
        let src = w.finish();
        assert_eq!(src.matches("uniform float u_alpha_ref;").count(), 1);
        assert!(src.starts_with("#version 330 core\n"));
        assert_eq!(
            w.uniforms(),
            [UniformSource::AlphaRef, UniformSource::Modelview]
        );
    }
}
