//! `FIXEDFUNC_TRACE=calls.c`: every call the library executes, written as the script
//! dialect (`ff::script::print`), so that `fixedfunc replay calls.c --size WxH` renders the
//! same image and `fixedfunc shaders calls.c` shows the programs it needed. What reaches
//! the file is what the pipeline executed: client arrays, buffer and display-list data
//! appear inlined where they were drawn (as glBegin/glEnd with the values read), texture
//! data as compound literals, a recorded error as a comment. One file per process; each
//! context and buffer size is announced in a comment. The pixel storage a command was read
//! with is written before it whenever it differs from what the file last set
//! (`glPixelStorei`), and pixel data is printed with its rows padded to that unpack
//! alignment, so the script reads the data back as the program gave it.
//!
//! Writes are buffered and flushed where the program's image is complete (glFinish,
//! glFlush, OSMesaMakeCurrent, OSMesaDestroyContext), not per call.
//!
//! A write that fails stops the trace with one message on stderr (the program itself goes
//! on: a trace is an observer, not part of the GL contract).

use std::fs::File;
use std::io::{BufWriter, Write};
use std::sync::Mutex;

use crate::ff::pixel_store::PixelStore;
use crate::ff::script::print_aligned;
use crate::ff::Command;

/// The environment variable naming the trace file.
pub const VARIABLE: &str = "FIXEDFUNC_TRACE";

enum State {
    Unopened,
    /// The file, and the pixel storage its calls have set so far.
    Writing(BufWriter<File>, PixelStore),
    Off,
}

static TRACE: Mutex<State> = Mutex::new(State::Unopened);

fn with_writer(f: impl FnOnce(&mut BufWriter<File>, &mut PixelStore) -> std::io::Result<()>) {
    let Ok(mut state) = TRACE.lock() else {
        return;
    };
    if let State::Unopened = *state {
        *state = match std::env::var_os(VARIABLE) {
            None => State::Off,
            Some(path) => match File::create(&path) {
                Ok(file) => {
                    let mut w = BufWriter::new(file);
                    let _ = writeln!(
                        w,
                        "/* fixedfunc trace: the GL calls one program made, as executed. */"
                    );
                    State::Writing(w, PixelStore::default())
                }
                Err(e) => {
                    eprintln!(
                        "fixedfunc: {VARIABLE}={}: cannot create it: {e}; no trace is written",
                        path.to_string_lossy()
                    );
                    State::Off
                }
            },
        };
    }
    if let State::Writing(w, store) = &mut *state {
        if let Err(e) = f(w, store) {
            eprintln!("fixedfunc: writing the {VARIABLE} file failed: {e}; the trace stops here");
            *state = State::Off;
        }
    }
}

/// Whether a trace is being written (checked once per context, so an untraced program
/// pays nothing per call).
pub fn enabled() -> bool {
    std::env::var_os(VARIABLE).is_some()
}

/// One executed command, read with the pixel storage `now`. Only the alignments are
/// written: a Command holds tight rows (the front end applied ROW_LENGTH, the skips,
/// SWAP_BYTES and LSB_FIRST), printed padded to the unpack alignment, so the replay reads
/// them with every other parameter at its default.
pub fn command(cmd: &Command, now: PixelStore) {
    with_writer(|w, written| {
        let names = [
            (
                "GL_PACK_ALIGNMENT",
                now.pack.alignment,
                written.pack.alignment,
            ),
            (
                "GL_UNPACK_ALIGNMENT",
                now.unpack.alignment,
                written.unpack.alignment,
            ),
        ];
        for (name, value, before) in names {
            if value != before {
                writeln!(w, "glPixelStorei({name}, {value});")?;
            }
        }
        *written = now;
        let text = print_aligned(std::slice::from_ref(cmd), now.unpack.alignment);
        w.write_all(text.as_bytes())
    });
}

/// Writes out what is buffered: at glFinish, glFlush, a make-current and a context's end,
/// the points where the program's image is complete.
pub fn flush() {
    with_writer(|w, _| w.flush());
}

/// A note: a context made current with a buffer of this size.
pub fn buffer(width: i32, height: i32, accum: bool) {
    let accum = if accum { " --accum" } else { "" };
    with_writer(|w, _| {
        writeln!(
            w,
            "/* OSMesaMakeCurrent: a {width}x{height} buffer (replay with --size {width}x{height}{accum}) */"
        )
    });
}
