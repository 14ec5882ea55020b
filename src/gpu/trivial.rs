//! The smallest real draw: one GLSL 330 program that places triangles given in clip space
//! and fills them with one colour. Context tests and `fixedfunc bench --only context` use
//! it to prove that a context renders; the fixed-function pipeline does not.

use glow::HasContext;

use super::{GpuContext, GpuError};

const VERTEX: &str = "#version 330 core
layout(location = 0) in vec3 position;
void main() { gl_Position = vec4(position, 1.0); }
";

const FRAGMENT: &str = "#version 330 core
uniform vec4 color;
out vec4 frag_color;
void main() { frag_color = color; }
";

/// A compiled flat-colour program with its vertex array and buffer.
pub struct FlatProgram {
    program: glow::Program,
    vao: glow::VertexArray,
    vbo: glow::Buffer,
    color: Option<glow::UniformLocation>,
}

impl FlatProgram {
    pub fn new(ctx: &GpuContext) -> Result<FlatProgram, GpuError> {
        let gl = ctx.gl();
        unsafe {
            let program = gl.create_program().map_err(GpuError::Object)?;
            for (kind, source) in [
                (glow::VERTEX_SHADER, VERTEX),
                (glow::FRAGMENT_SHADER, FRAGMENT),
            ] {
                let shader = gl.create_shader(kind).map_err(GpuError::Object)?;
                gl.shader_source(shader, source);
                gl.compile_shader(shader);
                if !gl.get_shader_compile_status(shader) {
                    return Err(GpuError::Object(format!(
                        "flat shader: {}",
                        gl.get_shader_info_log(shader)
                    )));
                }
                gl.attach_shader(program, shader);
                gl.delete_shader(shader);
            }
            gl.link_program(program);
            if !gl.get_program_link_status(program) {
                return Err(GpuError::Object(format!(
                    "flat program: {}",
                    gl.get_program_info_log(program)
                )));
            }
            let vao = gl.create_vertex_array().map_err(GpuError::Object)?;
            let vbo = gl.create_buffer().map_err(GpuError::Object)?;
            let color = gl.get_uniform_location(program, "color");
            Ok(FlatProgram {
                program,
                vao,
                vbo,
                color,
            })
        }
    }

    /// Draws triangles (three clip-space xyz vertices each) in `rgba`.
    pub fn draw(&self, ctx: &GpuContext, vertices: &[[f32; 3]], rgba: [f32; 4]) {
        let gl = ctx.gl();
        let bytes: Vec<u8> = vertices
            .iter()
            .flatten()
            .flat_map(|v| v.to_ne_bytes())
            .collect();
        unsafe {
            gl.use_program(Some(self.program));
            gl.uniform_4_f32(self.color.as_ref(), rgba[0], rgba[1], rgba[2], rgba[3]);
            gl.bind_vertex_array(Some(self.vao));
            gl.bind_buffer(glow::ARRAY_BUFFER, Some(self.vbo));
            gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, &bytes, glow::STREAM_DRAW);
            gl.enable_vertex_attrib_array(0);
            gl.vertex_attrib_pointer_f32(0, 3, glow::FLOAT, false, 12, 0);
            gl.draw_arrays(glow::TRIANGLES, 0, vertices.len() as i32);
            gl.bind_vertex_array(None);
            gl.use_program(None);
        }
    }

    pub fn delete(self, ctx: &GpuContext) {
        let gl = ctx.gl();
        unsafe {
            gl.delete_program(self.program);
            gl.delete_vertex_array(self.vao);
            gl.delete_buffer(self.vbo);
        }
    }
}
