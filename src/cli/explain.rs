//! `fixedfunc explain [SCENE] --technique T [--format c|script|markdown]`: a technique's
//! frame as the era wrote it — the same commands `render` executes, printed by the script
//! printer (`ff::script::print`), with the technique's own words at each pass
//! (`techniques::explain`).
//!
//! **Sections.** A frame is the plan's setup (once), its map passes (the first frame, and
//! again when the light or a caster moves) and its eye passes (every frame); each is a
//! [`Section`]: its place, the paragraph that explains it, its commands. The three formats
//! print the same sections:
//! - `script`: the replay dialect, each section headed by a C comment. `replay --size` must
//!   be the plan's framebuffer, which the image (its lower-left corner) shares with the
//!   light's map; glReadPixels fills `readback_N` and glTexImage2D reads it, as `replay`
//!   does by convention.
//! - `c`: the same text as the body of one C99 program on the OSMesa API: a context with
//!   the depth and stencil bits the plan's framebuffer asks for and an RGBA buffer of the
//!   framebuffer's size, the readback buffers as static arrays (of the type glReadPixels is
//!   given), a function per section, a GL error check after each, and the image's corner
//!   written as a PPM (top row first). Extension calls Mesa's library does not export
//!   (NV_register_combiners) are resolved through OSMesaGetProcAddress, so the program links
//!   against either library and says at run time which one lacks them.
//! - `markdown`: the module note, the figures that decide success, and per section its
//!   paragraph, its calls (draws summarised), the state its draws see as glGet answers it
//!   (only what differs from a fresh context; values the section changed in bold) and the
//!   programs the emulated path generates for them, printed as `shaders` prints them.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use fixedfunc::ff::{script, Capability, Command, FixedState, PixelType, ReadPixels, TexData};
use fixedfunc::pipeline::emulate::key::ShaderKey;
use fixedfunc::render::{apply_overrides, ImageSize, RenderError, MAX_IMAGE_SIZE};
use fixedfunc::report;
use fixedfunc::scene::{Limits, Scene};
use fixedfunc::techniques::explain::{self as notes, PassState, StateRow};
use fixedfunc::techniques::{self, Plan, Prepared};
use fixedfunc::vocab::{DepthRule, Named, TechniqueId};

use super::error::CliError;
use super::shadow_args::ShadowArgs;
use super::{pipelines, scene_arg, shaders};

/// What `explain` prints.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// One C99 program on the OSMesa API that renders the frame and writes it as a PPM.
    C,
    /// The replay dialect (`fixedfunc replay`, `fixedfunc shaders`), pass by pass.
    Script,
    /// A page: each pass's purpose, state table and GLSL, and the figures that decide it.
    Markdown,
}

/// Arguments of `explain`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Scene file (TOML); the built-in default scene when omitted.
    scene: Option<PathBuf>,
    /// Technique (default: the scene's `[shadow] technique`).
    #[arg(long, value_parser = pipelines::technique_parser())]
    technique: Option<TechniqueId>,
    /// What to print.
    #[arg(long, value_enum, default_value = "c")]
    format: Format,
    /// Image size WxH (default: the scene's).
    #[arg(long, value_name = "WxH", value_parser = scene_arg::parse_size)]
    size: Option<ImageSize>,
    /// Write to FILE instead of standard output.
    #[arg(long, value_name = "FILE")]
    out: Option<PathBuf>,
    #[command(flatten)]
    shadow: ShadowArgs,
}

pub fn run(args: Args, limits: Limits) -> Result<(), CliError> {
    let mut scene = scene_arg::load(args.scene.as_deref(), limits)?;
    args.shadow.apply(&mut scene);
    let scene = apply_overrides(&scene, args.size, args.technique);
    let frame = Frame::new(scene, args.scene.as_deref())?;
    let text = match args.format {
        Format::Script => script_text(&frame),
        Format::C => c_program(&frame),
        Format::Markdown => markdown(&frame),
    };
    match &args.out {
        Some(path) => Ok(report::write_file(path, text.as_bytes())?),
        None => out!("{text}"),
    }
}

/// A scene's technique, planned.
struct Frame {
    scene: Scene,
    id: TechniqueId,
    plan: Plan,
    /// `the default scene` or the file's path.
    scene_name: String,
}

impl Frame {
    fn new(scene: Scene, path: Option<&Path>) -> Result<Frame, CliError> {
        let (width, height) = (scene.image.width, scene.image.height);
        if width > MAX_IMAGE_SIZE || height > MAX_IMAGE_SIZE {
            return Err(RenderError::ImageTooLarge {
                width,
                height,
                max: MAX_IMAGE_SIZE,
            }
            .into());
        }
        let id = scene.shadow.technique;
        let prepared = Prepared::new(&scene);
        let plan =
            (techniques::technique(id).plan)(&scene, &prepared).map_err(RenderError::from)?;
        let fb = plan.framebuffer;
        if fb.width > MAX_IMAGE_SIZE || fb.height > MAX_IMAGE_SIZE {
            return Err(RenderError::MapTooLarge {
                size: scene.shadow.map_size,
                max: MAX_IMAGE_SIZE,
            }
            .into());
        }
        Ok(Frame {
            scene,
            id,
            plan,
            scene_name: scene_arg::name(path),
        })
    }

    /// The setup (when there is one), then every pass of a frame that makes its maps.
    fn sections(&self) -> Vec<Section<'_>> {
        let mut out = Vec::new();
        if !self.plan.setup.is_empty() {
            out.push(Section {
                stage: Stage::Setup,
                name: "setup",
                number: 0,
                note: notes::SETUP_NOTE,
                commands: &self.plan.setup,
            });
        }
        let maps = self.plan.maps.iter().map(|p| (Stage::Maps, p));
        let eye = self.plan.passes.iter().map(|p| (Stage::Eye, p));
        for (i, (stage, pass)) in maps.chain(eye).enumerate() {
            out.push(Section {
                stage,
                name: pass.name,
                number: i + 1,
                note: notes::pass_note(self.id, pass.name)
                    .unwrap_or("(this pass has no note in techniques::explain)"),
                commands: &pass.commands,
            });
        }
        out
    }

    fn title(&self) -> String {
        let t = techniques::technique(self.id);
        format!(
            "`{}` on {}, {}×{}: {}",
            self.id.name(),
            self.scene_name,
            self.scene.image.width,
            self.scene.image.height,
            t.summary
        )
    }

    /// `--size` of `replay` for the printed script: the framebuffer's.
    fn replay_size(&self) -> String {
        let fb = self.plan.framebuffer;
        format!("{}x{}", fb.width, fb.height)
    }

    /// `replay`'s options beyond the size: `--accum` when the plan uses the accumulation
    /// buffer (glAccum), which a replay's window has only when asked for.
    fn replay_extra(&self) -> &'static str {
        if self.plan.needs_accumulation() {
            " --accum"
        } else {
            ""
        }
    }
}

/// When a section runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Stage {
    Setup,
    Maps,
    Eye,
}

/// One part of the frame: the setup or a pass.
struct Section<'p> {
    stage: Stage,
    name: &'static str,
    /// 1-based pass number (0 for the setup).
    number: usize,
    note: &'static str,
    commands: &'p [Command],
}

impl Section<'_> {
    /// `pass 2 of 5: readback (makes the maps: …)`.
    fn heading(&self, passes: usize) -> String {
        match self.stage {
            Stage::Setup => "setup (once, before the first frame)".to_string(),
            Stage::Maps => format!(
                "pass {} of {passes}: {} (makes the maps: on the first frame, and again when \
                 the light or a caster moves)",
                self.number, self.name
            ),
            Stage::Eye => format!(
                "pass {} of {passes}: {} (every frame)",
                self.number, self.name
            ),
        }
    }

    /// The C function that runs it: `setup`, `pass_3_big_lit`.
    fn function(&self) -> String {
        match self.stage {
            Stage::Setup => "setup".to_string(),
            _ => format!("pass_{}_{}", self.number, self.name.replace('-', "_")),
        }
    }
}

/// `text` wrapped at `width` columns.
fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines = Vec::new();
    let mut line = String::new();
    for word in text.split_whitespace() {
        if !line.is_empty() && line.chars().count() + 1 + word.chars().count() > width {
            lines.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
    }
    if !line.is_empty() {
        lines.push(line);
    }
    lines
}

/// A C block comment of `lines` (each prefixed with ` * `); nothing in them can end it.
fn c_comment(lines: &[String]) -> String {
    let mut out = String::from("/*");
    for (i, l) in lines.iter().enumerate() {
        let l = l.replace("*/", "* /").replace("/*", "/ *");
        match (i, l.is_empty()) {
            (0, _) => out.push_str(&format!(" {l}\n")),
            (_, true) => out.push_str(" *\n"),
            (_, false) => out.push_str(&format!(" * {l}\n")),
        }
    }
    out.push_str(" */\n");
    out
}

/// A section's heading and paragraph as a C comment.
fn section_comment(s: &Section, passes: usize) -> String {
    let mut lines = wrap(&format!("---- {} ----", s.heading(passes)), 86);
    lines.extend(wrap(s.note, 86));
    c_comment(&lines)
}

/// Where glReadPixels leaves the map, for the header: `readback_1` …
fn readback_names(sections: &[Section]) -> Vec<String> {
    readbacks(sections)
        .keys()
        .map(|slot| format!("readback_{slot}"))
        .collect()
}

fn script_text(frame: &Frame) -> String {
    let sections = frame.sections();
    let passes = frame.plan.pass_count();
    let fb = frame.plan.framebuffer;
    let mut header = vec![
        frame.title(),
        String::new(),
        format!(
            "Written by `fixedfunc explain --format script`; `fixedfunc replay FILE --size {}{}` \
             runs it on the framebuffer the plan asks for: {}×{}, shared by the image (its \
             lower-left {}×{}, what `render` writes) and the light's map, drawn in the same \
             corner before the eye passes.",
            frame.replay_size(),
            frame.replay_extra(),
            fb.width,
            fb.height,
            frame.scene.image.width,
            frame.scene.image.height
        ),
    ];
    let names = readback_names(&sections);
    if !names.is_empty() {
        header.push(String::new());
        header.push(format!(
            "glReadPixels writes {} and glTexImage2D reads it back: `replay` keeps it between \
             the two; a C program declares it (`--format c` writes one).",
            names.join(", ")
        ));
    }
    let wrapped: Vec<String> = header
        .iter()
        .flat_map(|p| {
            if p.is_empty() {
                vec![String::new()]
            } else {
                wrap(p, 86)
            }
        })
        .collect();
    let mut out = c_comment(&wrapped);
    for s in &sections {
        out.push('\n');
        out.push_str(&section_comment(s, passes));
        out.push_str(&script::print(s.commands));
    }
    out
}

/// Each readback slot's C element type and the number of elements it must hold (the
/// largest glReadPixels into it, rows padded to GL_PACK_ALIGNMENT 4, GL's default).
fn readbacks(sections: &[Section]) -> BTreeMap<u32, (&'static str, usize)> {
    let mut out: BTreeMap<u32, (&'static str, usize)> = BTreeMap::new();
    for cmd in sections.iter().flat_map(|s| s.commands) {
        if let Command::ReadPixels(r) = cmd {
            let (ty, size) = element(r.ty);
            let count = readback_bytes(r).div_ceil(size);
            let entry = out.entry(r.slot).or_insert((ty, 0));
            entry.1 = entry.1.max(count);
        }
    }
    out
}

fn readback_bytes(r: &ReadPixels) -> usize {
    let row = r.width.max(0) as usize * r.ty.group_bytes(r.format);
    fixedfunc::ff::pixel_store::PixelStore::stride(row, 4) * r.height.max(0) as usize
}

/// The C element type of a glReadPixels destination and its size in bytes.
fn element(ty: PixelType) -> (&'static str, usize) {
    match ty {
        PixelType::UnsignedShort => ("GLushort", 2),
        PixelType::UnsignedInt => ("GLuint", 4),
        PixelType::Float => ("GLfloat", 4),
        _ => ("GLubyte", 1),
    }
}

/// The client conversions of FLOAT depth readbacks the sections use: helper name, type,
/// rule, and the most values one conversion reads (the texture's width × height).
fn depth_helpers(sections: &[Section]) -> BTreeMap<String, (PixelType, DepthRule, usize)> {
    let mut out = BTreeMap::new();
    for cmd in sections.iter().flat_map(|s| s.commands) {
        let Command::TexImage(t) = cmd else { continue };
        let TexData::ConvertedDepth { ty, rule, .. } = &t.data else {
            continue;
        };
        let (ty, rule) = (*ty, *rule);
        let size = match ty {
            PixelType::UnsignedShort => "ushort",
            _ => "ubyte",
        };
        let rule_name = match rule {
            DepthRule::Truncate => "truncate",
            DepthRule::Round => "round",
        };
        let name = format!("fixedfunc_depth_{size}_{rule_name}");
        let values = (t.width.max(0) * t.height.max(0) * t.depth.max(1)) as usize;
        let entry = out.entry(name).or_insert((ty, rule, 0));
        entry.2 = entry.2.max(values);
    }
    out
}

/// A depth conversion as C: ⌊z·M⌋ or ⌊z·M + ½⌋ of z clamped to [0, 1], NaN as 0
/// (`gpu::readback`'s rules).
fn depth_helper_c(name: &str, ty: PixelType, rule: DepthRule, values: usize) -> String {
    let (ctype, max) = match ty {
        PixelType::UnsignedShort => ("GLushort", "65535.0"),
        _ => ("GLubyte", "255.0"),
    };
    let half = match rule {
        DepthRule::Truncate => "",
        DepthRule::Round => " + 0.5",
    };
    format!(
        "/* The program's own float-to-integer depth rule (the scene's `readback`): FLOAT \
         depths\n * read back, converted on the CPU before glTexImage2D. */\n\
         static const void *{name}(const void *depths) {{\n\
         \x20   static {ctype} out[{values}];\n\
         \x20   const GLfloat *z = depths;\n\
         \x20   for (size_t i = 0; i < {values}; i++) {{\n\
         \x20       double v = z[i] != z[i] ? 0.0 : z[i] < 0 ? 0.0 : z[i] > 1 ? 1.0 : z[i];\n\
         \x20       double n = floor(v * {max}{half});\n\
         \x20       out[i] = ({ctype})(n > {max} ? {max} : n);\n\
         \x20   }}\n\
         \x20   return out;\n\
         }}\n"
    )
}

/// The extension functions the body calls that Mesa's libOSMesa does not export: every
/// `gl…NV` identifier followed by `(`.
fn nv_functions(body: &str) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    for (i, _) in body.match_indices("gl") {
        let rest = &body[i..];
        let len = rest
            .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .unwrap_or(rest.len());
        let name = &rest[..len];
        let starts_word = i == 0 || !body[..i].ends_with(|c: char| c.is_ascii_alphanumeric());
        if starts_word
            && name.ends_with("NV")
            && rest[len..].starts_with('(')
            && !out.iter().any(|n| n == name)
        {
            out.push(name.to_string());
        }
    }
    out
}

/// A section's commands as the C function's body: the script, but for the reset's
/// glDisable(GL_REGISTER_COMBINERS_NV), which a library without the extension refuses
/// (INVALID_ENUM): it runs only where the extension exists, as the native path skips it.
fn c_body(commands: &[Command]) -> String {
    let mut out = String::new();
    for cmd in commands {
        match cmd {
            Command::Disable(Capability::RegisterCombiners) => {
                out.push_str("if (nv_register_combiners) glDisable(GL_REGISTER_COMBINERS_NV);\n")
            }
            other => out.push_str(&script::print(std::slice::from_ref(other))),
        }
    }
    out
}

/// The longest array literal left in the calls; longer ones become static arrays.
const INLINE_ARRAY: usize = 400;

/// Moves the long array literals of `bodies` — the scene's vertices, normals and indices,
/// the ramps' texels — into static arrays, one per distinct content (a mesh drawn by three
/// passes is written once), named for the call that reads them: `positions_0`,
/// `indices_2`. Returns their declarations. Literals never nest in what the plans print.
fn hoist_arrays(bodies: &mut [String]) -> String {
    let mut arrays: Vec<(String, String, String)> = Vec::new(); // (name, type, values)
    for body in bodies.iter_mut() {
        let mut out = String::with_capacity(body.len());
        let mut rest = body.as_str();
        while let Some((start, ty, open)) = next_literal(rest) {
            let Some(len) = rest[open..].find('}') else {
                break;
            };
            let values = &rest[open + 1..open + len];
            out.push_str(&rest[..start]);
            if values.len() <= INLINE_ARRAY {
                out.push_str(&rest[start..open + len + 1]);
            } else {
                let line_start = rest[..start].rfind('\n').map_or(0, |i| i + 1);
                let kind = array_kind(&rest[line_start..start]);
                let name = match arrays.iter().find(|(_, t, v)| t == ty && v == values) {
                    Some((name, _, _)) => name.clone(),
                    None => {
                        let n = arrays
                            .iter()
                            .filter(|(a, _, _)| a.starts_with(kind))
                            .count();
                        let name = format!("{kind}_{n}");
                        arrays.push((name.clone(), ty.to_string(), values.to_string()));
                        name
                    }
                };
                out.push_str(&name);
            }
            rest = &rest[open + len + 1..];
        }
        out.push_str(rest);
        *body = out;
    }
    let mut decls = String::new();
    if !arrays.is_empty() {
        decls.push_str(
            "/* The scene's geometry and the ramps' texels, as static arrays: each is written \
             once and\n * read by every pass that draws it. */\n",
        );
    }
    for (name, ty, values) in &arrays {
        let _ = writeln!(decls, "static const {ty} {name}[] = {{");
        for line in wrap(values, 92) {
            let _ = writeln!(decls, "    {line}");
        }
        decls.push_str("};\n");
    }
    if !arrays.is_empty() {
        decls.push('\n');
    }
    decls
}

/// The next `(GLfloat[]){` (or another element type): where it starts, the element type,
/// and where its `{` is.
fn next_literal(text: &str) -> Option<(usize, &'static str, usize)> {
    [
        "GLfloat", "GLuint", "GLushort", "GLubyte", "GLint", "GLshort", "GLbyte",
    ]
    .into_iter()
    .filter_map(|ty| {
        let pattern = format!("({ty}[]){{");
        text.find(&pattern)
            .map(|at| (at, ty, at + pattern.len() - 1))
    })
    .min_by_key(|(at, _, _)| *at)
}

/// What an array is, from the call it is given to.
fn array_kind(call: &str) -> &'static str {
    let call = call.trim_start();
    [
        ("glVertexPointer", "positions"),
        ("glNormalPointer", "normals"),
        ("glColorPointer", "colours"),
        ("glTexCoordPointer", "texcoords"),
        ("glDrawElements", "indices"),
        ("glTexImage", "texels"),
    ]
    .into_iter()
    .find(|(prefix, _)| call.starts_with(prefix))
    .map_or("data", |(_, kind)| kind)
}

/// Whether the frame enables NV_register_combiners (and so cannot run without them).
fn needs_combiners(sections: &[Section]) -> bool {
    sections
        .iter()
        .flat_map(|s| s.commands)
        .any(|c| matches!(c, Command::Enable(Capability::RegisterCombiners)))
}

fn c_program(frame: &Frame) -> String {
    let sections = frame.sections();
    let passes = frame.plan.pass_count();
    let mut bodies: Vec<String> = sections.iter().map(|s| c_body(s.commands)).collect();
    let arrays = hoist_arrays(&mut bodies);
    let nv = nv_functions(&bodies.concat());
    let required = needs_combiners(&sections);
    let mut out = c_header(frame, required);
    let buffers = readbacks(&sections);
    if !buffers.is_empty() {
        out.push_str("/* glReadPixels' destinations: the map on its way to a texture. */\n");
    }
    for (slot, (ty, count)) in buffers {
        out.push_str(&format!("static {ty} readback_{slot}[{count}];\n"));
    }
    for name in &nv {
        let pfn = format!("PFN{}PROC", name.to_uppercase());
        out.push_str(&format!(
            "static {pfn} p_{name};\n#define {name} p_{name}\n"
        ));
    }
    out.push('\n');
    out.push_str(&arrays);
    for (name, (ty, rule, values)) in depth_helpers(&sections) {
        out.push_str(&depth_helper_c(&name, ty, rule, values));
        out.push('\n');
    }
    for (s, body) in sections.iter().zip(&bodies) {
        out.push_str(&section_comment(s, passes));
        out.push_str(&format!("static void {}(void) {{\n", s.function()));
        for line in body.lines() {
            out.push_str("    ");
            out.push_str(line);
            out.push('\n');
        }
        out.push_str("}\n\n");
    }
    out.push_str(C_SUPPORT);
    out.push_str(&c_main(frame, &sections, &nv, required));
    out
}

/// The program's opening comment (the technique's own note), includes and sizes.
fn c_header(frame: &Frame, needs_combiners: bool) -> String {
    let fb = frame.plan.framebuffer;
    let (w, h) = (frame.scene.image.width, frame.scene.image.height);
    let name = frame.id.name();
    let mut lines = wrap(&frame.title(), 86);
    lines.push(String::new());
    lines.extend(notes::overview(frame.id).lines().map(str::to_string));
    lines.push(String::new());
    let mut usage = format!(
        "Written by `fixedfunc explain --format c`. Build and run, on Mesa's OSMesa or on \
         fixedfunc's library: `cc -std=c99 {name}.c -o {name} -lOSMesa -lm && ./{name} \
         [out.ppm]`, and `LD_LIBRARY_PATH=$(fixedfunc osmesa-dir) ./{name}`. It draws into a \
         {}×{} buffer — the image and the light's map share it, as on the era's hardware — \
         and writes the image, its lower-left {w}×{h}, as a PPM ({name}.ppm by default). \
         Exit status 1 when GL raised an error (each is printed with its pass), 2 when no \
         context could be made or the image not written.",
        fb.width, fb.height
    );
    if needs_combiners {
        usage.push_str(
            " This technique uses NV_register_combiners, which Mesa's OSMesa does not have: \
             the program resolves it through OSMesaGetProcAddress and runs only on \
             fixedfunc's library.",
        );
    }
    lines.extend(wrap(&usage, 86));
    let mut out = c_comment(&lines);
    out.push_str(
        "#define GL_GLEXT_PROTOTYPES 1\n#include <GL/gl.h>\n#include <GL/glext.h>\n\
         #include <GL/osmesa.h>\n#include <math.h>\n#include <stddef.h>\n#include <stdio.h>\n\
         #include <stdlib.h>\n#include <string.h>\n\n",
    );
    let stencil = if fb.stencil { 8 } else { 0 };
    let _ = write!(
        out,
        "/* The framebuffer the plan asks for: {} depth bits{}, {} stencil bits. */\n\
         #define FB_WIDTH {}\n#define FB_HEIGHT {}\n#define DEPTH_BITS {}\n\
         #define STENCIL_BITS {stencil}\n/* The image: the framebuffer's lower-left corner. */\n\
         #define WIDTH {w}\n#define HEIGHT {h}\n\n\
         /* Whether the library has NV_register_combiners (Mesa's has not): the passes' \
         closing\n * glDisable(GL_REGISTER_COMBINERS_NV) is made only where it exists. */\n\
         static int nv_register_combiners;\n\n",
        fb.depth.bits(),
        if fb.depth.is_float() {
            " (a float buffer in `render`; OSMesa's is integer)"
        } else {
            ""
        },
        stencil,
        fb.width,
        fb.height,
        fb.depth.bits()
    );
    out
}

/// The error check and the PPM writer, the same for every program.
const C_SUPPORT: &str = "\
static int gl_errors;

/* Every GL error a section raised, named with the section. */
static void check(const char *section) {
    for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError()) {
        fprintf(stderr, \"%s: GL error 0x%04x\\n\", section, (unsigned)e);
        gl_errors++;
    }
}

/* The image, the lower-left WIDTH x HEIGHT of the buffer (bottom row first, as OSMesa
 * keeps it), as a binary PPM, top row first. */
static int write_ppm(const char *path, const GLubyte *rgba) {
    FILE *f = fopen(path, \"wb\");
    if (!f) return 0;
    fprintf(f, \"P6\\n%d %d\\n255\\n\", WIDTH, HEIGHT);
    for (int y = HEIGHT - 1; y >= 0; y--)
        for (int x = 0; x < WIDTH; x++)
            fwrite(rgba + 4 * ((size_t)y * FB_WIDTH + x), 1, 3, f);
    return fclose(f) == 0;
}

";

fn c_main(frame: &Frame, sections: &[Section], nv: &[String], required: bool) -> String {
    let mut out = format!(
        "int main(int argc, char **argv) {{\n\
         \x20   const char *out = argc > 1 ? argv[1] : \"{}.ppm\";\n\
         \x20   OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, DEPTH_BITS, STENCIL_BITS, {}, NULL);\n\
         \x20   GLubyte *buffer = malloc((size_t)FB_WIDTH * FB_HEIGHT * 4);\n\
         \x20   if (!ctx || !buffer || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, FB_WIDTH, FB_HEIGHT)) {{\n\
         \x20       fprintf(stderr, \"%s: no OSMesa context of %dx%d with %d depth and %d stencil bits\\n\",\n\
         \x20               argv[0], FB_WIDTH, FB_HEIGHT, DEPTH_BITS, STENCIL_BITS);\n\
         \x20       if (ctx) OSMesaDestroyContext(ctx);\n\
         \x20       free(buffer);\n\
         \x20       return 2;\n\
         \x20   }}\n",
        frame.id.name(),
        // glAccum needs the window's accumulation buffer (Mesa gives 16 bits per channel).
        if frame.plan.needs_accumulation() { 16 } else { 0 },
    );
    out.push_str(
        "    const char *extensions = (const char *)glGetString(GL_EXTENSIONS);\n\
         \x20   nv_register_combiners = extensions && strstr(extensions, \"GL_NV_register_combiners\") != NULL;\n",
    );
    if required {
        out.push_str(
            "    if (!nv_register_combiners) {\n\
             \x20       fprintf(stderr, \"%s: this library has no NV_register_combiners (Mesa's OSMesa has \
             none): run it with LD_LIBRARY_PATH=$(fixedfunc osmesa-dir)\\n\", argv[0]);\n\
             \x20       OSMesaDestroyContext(ctx);\n\
             \x20       free(buffer);\n\
             \x20       return 2;\n\
             \x20   }\n",
        );
    }
    for name in nv {
        let pfn = format!("PFN{}PROC", name.to_uppercase());
        let _ = writeln!(
            out,
            "    p_{name} = ({pfn})OSMesaGetProcAddress(\"{name}\");"
        );
    }
    for s in sections {
        let _ = writeln!(out, "    {}();\n    check(\"{}\");", s.function(), s.name);
    }
    out.push_str(
        "    glFinish();\n\
         \x20   int written = write_ppm(out, buffer);\n\
         \x20   OSMesaDestroyContext(ctx);\n\
         \x20   free(buffer);\n\
         \x20   if (!written) {\n\
         \x20       fprintf(stderr, \"%s: cannot write %s\\n\", argv[0], out);\n\
         \x20       return 2;\n\
         \x20   }\n\
         \x20   if (gl_errors) {\n\
         \x20       fprintf(stderr, \"%s: %d GL error(s)\\n\", argv[0], gl_errors);\n\
         \x20       return 1;\n\
         \x20   }\n\
         \x20   return 0;\n\
         }\n",
    );
    out
}

/// One section's calls for the page: each command printed, a draw summarised by its
/// primitive and vertex count (its vertices are in the script).
fn calls_summary(commands: &[Command]) -> String {
    let mut out = String::new();
    for cmd in commands {
        match cmd {
            Command::Draw(g) => {
                let primitive =
                    fixedfunc::ff::glenum::GlEnum::gl_name(g.primitive).unwrap_or("GL_TRIANGLES");
                let _ = writeln!(
                    out,
                    "/* draw: {primitive}, {} vertices */",
                    g.vertex_count()
                );
            }
            other => out.push_str(&script::print(std::slice::from_ref(other))),
        }
    }
    out
}

fn markdown(frame: &Frame) -> String {
    let mut out = format!("# {}\n\n", frame.title());
    out.push_str(&notes::overview(frame.id));
    out.push_str("\n## The figures that decide it\n\n| figure | value |\n|---|---|\n");
    for f in notes::figures(&frame.scene) {
        let _ = writeln!(out, "| {} | {} |", cell(&f.name), cell(&f.value));
    }
    let fb = frame.plan.framebuffer;
    let _ = write!(
        out,
        "\n## The frame, pass by pass\n\n\
         The framebuffer is {}×{} ({} depth bits{}); the image is its lower-left {}×{}. The \
         setup runs once, the map passes on the first frame and again when the light or a \
         caster moves, the eye passes every frame. Each state table lists what glGet answers \
         differently from a fresh context while the pass draws — a column per run of draws \
         with the same state — or, for a pass that draws nothing, what it leaves; values the \
         pass itself changed are in bold. The modelview matrix, the material and the current \
         normal, set per object, are left out. `fixedfunc explain --format script` prints \
         every call with its vertices.\n",
        fb.width,
        fb.height,
        fb.depth.bits(),
        if fb.stencil { ", 8 stencil bits" } else { "" },
        frame.scene.image.width,
        frame.scene.image.height
    );
    let precision = frame.scene.shadow.precision;
    let mut state = FixedState::new();
    let mut keys: Vec<ShaderKey> = Vec::new();
    let sections = frame.sections();
    for s in &sections {
        let before = notes::state_rows(&state);
        let mut used: Vec<usize> = Vec::new();
        let states = notes::pass_states(&mut state, s.commands, &mut |st| {
            let key = ShaderKey::from_state(st, precision);
            let i = match keys.iter().position(|k| *k == key) {
                Some(i) => i,
                None => {
                    keys.push(key);
                    keys.len() - 1
                }
            };
            if !used.contains(&i) {
                used.push(i);
            }
        });
        let _ = write!(
            out,
            "\n### {}\n\n{}\n\n```c\n{}```\n\n",
            heading_case(&s.heading(frame.plan.pass_count())),
            s.note,
            calls_summary(s.commands)
        );
        out.push_str(&state_table(&states, &before));
        if !used.is_empty() {
            let list: Vec<String> = used.iter().map(|i| format!("program {i}")).collect();
            let _ = writeln!(
                out,
                "\nOn the emulated path its draws run {} (below).",
                list.join(", ")
            );
        }
    }
    out.push_str(
        "\n## Programs\n\nThe GLSL the emulated pipeline generates for these draws (precision \
         of the scene's `[shadow] precision`), as `fixedfunc shaders` prints it: each \
         program's key, then its vertex and fragment shaders.\n",
    );
    for (i, key) in keys.iter().enumerate() {
        let _ = write!(out, "\n```text\n{}\n```\n", shaders::program_text(i, key));
    }
    out
}

/// `Pass 1 of 5: …` from `pass 1 of 5: …`.
fn heading_case(text: &str) -> String {
    let mut c = text.chars();
    c.next()
        .map_or_else(String::new, |f| f.to_uppercase().chain(c).collect())
}

/// A markdown table cell: no `|` and no line break.
fn cell(text: &str) -> String {
    text.replace('|', "\\|").replace('\n', " ")
}

/// The state of a pass's draws as one table: a row per state that differs from a fresh
/// context somewhere in the pass, a column per run of draws; bold where the pass changed it.
fn state_table(states: &[PassState], before: &[StateRow]) -> String {
    let mut names: Vec<(&str, &str)> = Vec::new();
    for r in states.iter().flat_map(|s| &s.rows) {
        if !names.contains(&(r.group.as_str(), r.name.as_str())) {
            names.push((r.group.as_str(), r.name.as_str()));
        }
    }
    if names.is_empty() {
        return "Every state is GL's default.\n".to_string();
    }
    let columns: Vec<String> = states
        .iter()
        .map(|s| match s.draws {
            None => "left by the pass".to_string(),
            Some((a, b)) if a == b => format!("draw {}", a + 1),
            Some((a, b)) => format!("draws {}–{}", a + 1, b + 1),
        })
        .collect();
    let mut out = format!(
        "| state | {} |\n|---|{}\n",
        columns.join(" | "),
        "---|".repeat(columns.len())
    );
    let find = |rows: &[StateRow], group: &str, name: &str| {
        rows.iter()
            .find(|r| r.group == group && r.name == name)
            .map(|r| r.value.clone())
    };
    for (group, name) in names {
        let label = match group {
            "" => format!("`{name}`"),
            g => format!("{g}: `{name}`"),
        };
        let was = find(before, group, name);
        let values: Vec<String> = states
            .iter()
            .map(|s| match find(&s.rows, group, name) {
                None => "—".to_string(),
                Some(v) if Some(&v) != was.as_ref() => format!("**{}**", cell(&v)),
                Some(v) => cell(&v),
            })
            .collect();
        let _ = writeln!(out, "| {label} | {} |", values.join(" | "));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn words_wrap_and_comments_cannot_close_early() {
        assert_eq!(wrap("a bb ccc dddd", 6), vec!["a bb", "ccc", "dddd"]);
        let c = c_comment(&["title".into(), String::new(), "x */ y /* z".into()]);
        assert_eq!(c, "/* title\n *\n * x * / y / * z\n */\n");
    }

    #[test]
    fn only_nv_calls_are_resolved_at_run_time() {
        let body = "glEnable(GL_REGISTER_COMBINERS_NV);\nglCombinerInputNV(GL_COMBINER0_NV);\n\
                    glFinalCombinerInputNV(GL_VARIABLE_A_NV);\nglCombinerInputNV(1);\n";
        assert_eq!(
            nv_functions(body),
            vec!["glCombinerInputNV", "glFinalCombinerInputNV"]
        );
    }
}
