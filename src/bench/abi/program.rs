//! The benchmark program: `benches/c/abi_bench.c`, embedded in the binary, written to a
//! private temporary folder and compiled there with the system's C compiler (`$CC`, split
//! on whitespace as make does, else `cc`) against Mesa's `GL/osmesa.h`, linked with
//! `-lOSMesa`; the folder goes when the [`Program`] is dropped.
//!
//! A run is one child process on one library: Mesa's `libOSMesa.so.8` found by the loader
//! as any program finds it (`LD_LIBRARY_PATH` removed), or the layer's with
//! `LD_LIBRARY_PATH` set to its folder. The child is waited for on every path: its guard
//! kills and reaps it when the run fails or takes longer than [`RUN_TIMEOUT`], and the
//! kernel kills it if this process dies first (`PR_SET_PDEATHSIG`), so no run outlives
//! the bench. `FIXEDFUNC_TRACE` is removed from the child's environment: a traced run
//! would time the trace. The run's heap setting reaches the child as `GLIBC_TUNABLES`.

use std::io::Read;
use std::os::unix::process::CommandExt;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, ExitStatus, Stdio};
use std::sync::atomic::{AtomicU32, Ordering};
use std::time::{Duration, Instant};

use super::output::{self, RunOutput};
use super::{AbiError, AbiMode, Heap, Library};
use crate::vocab::Named;

/// The program's source, as compiled.
pub const SOURCE: &str = include_str!("../../../benches/c/abi_bench.c");
/// The name the loader looks for, Mesa's and the layer's alike.
pub const SONAME: &str = "libOSMesa.so.8";
/// The longest one run may take before it is killed.
pub const RUN_TIMEOUT: Duration = Duration::from_secs(120);

/// The compiled program in its temporary folder (removed on drop).
#[derive(Debug)]
pub struct Program {
    folder: PathBuf,
    exe: PathBuf,
}

/// Where each library is: Mesa's through the loader's own search, the layer's in a folder
/// holding it as `libOSMesa.so.8` (what `fixedfunc osmesa-dir` prints).
#[derive(Clone, Debug)]
pub struct Libraries {
    pub fixedfunc_dir: PathBuf,
}

impl Program {
    /// Writes the source to a new temporary folder and compiles it.
    pub fn compile() -> Result<Program, AbiError> {
        static NEXT: AtomicU32 = AtomicU32::new(0);
        let folder = std::env::temp_dir().join(format!(
            "fixedfunc-abi-bench-{}-{}",
            std::process::id(),
            NEXT.fetch_add(1, Ordering::Relaxed)
        ));
        let io = |what: &str, path: &Path, e: std::io::Error| AbiError::Io {
            what: format!("{what} {}", path.display()),
            reason: e.to_string(),
        };
        std::fs::create_dir_all(&folder).map_err(|e| io("cannot create", &folder, e))?;
        // From here on the folder is removed on every path, by the Program's drop.
        let program = Program {
            exe: folder.join("abi_bench"),
            folder,
        };
        let source = program.folder.join("abi_bench.c");
        std::fs::write(&source, SOURCE).map_err(|e| io("cannot write", &source, e))?;
        let cc = compiler();
        let (tool, args) = cc.split_first().ok_or(AbiError::CompilerMissing {
            compiler: String::new(),
            reason: "CC is empty".into(),
        })?;
        let out = Command::new(tool)
            .args(args)
            .args(["-std=c99", "-O2", "-Wall", "-o"])
            .arg(&program.exe)
            .arg(&source)
            .args(["-lOSMesa", "-lm"])
            .output()
            .map_err(|e| AbiError::CompilerMissing {
                compiler: cc.join(" "),
                reason: e.to_string(),
            })?;
        if !out.status.success() {
            return Err(compile_error(
                &cc.join(" "),
                &String::from_utf8_lossy(&out.stderr),
            ));
        }
        Ok(program)
    }

    /// The executable (for running it by hand: `abi_bench MODE FRAMES [OUT.ppm]`).
    pub fn path(&self) -> &Path {
        &self.exe
    }

    /// One run of `frames` frames of `mode` on `library` under `heap`; `image` receives the last frame
    /// as a PPM. The output must show the library asked for: Mesa's vendor is not
    /// `fixedfunc`, the layer's is.
    pub fn run(
        &self,
        libraries: &Libraries,
        library: Library,
        mode: AbiMode,
        heap: Heap,
        frames: u32,
        image: Option<&Path>,
    ) -> Result<RunOutput, AbiError> {
        let mut cmd = Command::new(&self.exe);
        cmd.arg(mode.name()).arg(frames.to_string());
        if let Some(image) = image {
            cmd.arg(image);
        }
        cmd.env_remove("FIXEDFUNC_TRACE");
        let inherited = std::env::var("GLIBC_TUNABLES").ok();
        if let Some(tunables) = heap.tunables(inherited.as_deref()) {
            cmd.env("GLIBC_TUNABLES", tunables);
        }
        match library {
            Library::Mesa => {
                cmd.env_remove("LD_LIBRARY_PATH");
            }
            Library::Fixedfunc => {
                let lib = libraries.fixedfunc_dir.join(SONAME);
                // A link to a missing file counts as missing: the loader would then
                // quietly take Mesa's from its own search.
                if !lib.exists() {
                    return Err(AbiError::LibraryMissing { path: lib });
                }
                cmd.env("LD_LIBRARY_PATH", &libraries.fixedfunc_dir);
            }
        }
        let (status, stdout, stderr) = run_child(cmd, RUN_TIMEOUT, library, mode)?;
        if !status.success() {
            return Err(run_error(library, mode, status, stderr));
        }
        let out = output::parse(&stdout).map_err(|e| AbiError::Run {
            library,
            mode,
            source: Box::new(e),
        })?;
        let on_fixedfunc = out.vendor == "fixedfunc";
        if on_fixedfunc != (library == Library::Fixedfunc) || out.mode != mode {
            return Err(AbiError::WrongLibrary {
                library,
                mode,
                vendor: out.vendor,
                renderer: out.renderer,
            });
        }
        Ok(out)
    }
}

impl Drop for Program {
    fn drop(&mut self) {
        // Nothing is left to report a failed removal to; the folder is in the temp dir.
        let _ = std::fs::remove_dir_all(&self.folder);
    }
}

/// `$CC` split on whitespace, else `cc`.
fn compiler() -> Vec<String> {
    match std::env::var("CC") {
        Ok(cc) if !cc.trim().is_empty() => cc.split_whitespace().map(String::from).collect(),
        _ => vec!["cc".to_string()],
    }
}

/// A failed compile: a missing header or library names the package that has it.
fn compile_error(compiler: &str, stderr: &str) -> AbiError {
    let stderr = stderr.trim().to_string();
    if stderr.contains("osmesa.h") || stderr.contains("GL/gl.h") || stderr.contains("-lOSMesa") {
        AbiError::HeaderMissing { stderr }
    } else {
        AbiError::Compile {
            compiler: compiler.to_string(),
            stderr,
        }
    }
}

/// A failed run: the loader not finding Mesa's library is named as such.
fn run_error(library: Library, mode: AbiMode, status: ExitStatus, stderr: String) -> AbiError {
    let stderr = stderr.trim().to_string();
    if library == Library::Mesa && stderr.contains(SONAME) && stderr.contains("cannot open") {
        return AbiError::MesaMissing { stderr };
    }
    AbiError::Failed {
        library,
        mode,
        status: status.to_string(),
        stderr,
    }
}

/// Kills and reaps the child unless it has been reaped already.
struct Reaped(Child);

impl Drop for Reaped {
    fn drop(&mut self) {
        if let Ok(None) = self.0.try_wait() {
            let _ = self.0.kill();
        }
        let _ = self.0.wait();
    }
}

/// Runs the command to its end (or kills it at `timeout`), with its output read by two
/// threads so that neither pipe can fill and stall it.
fn run_child(
    mut cmd: Command,
    timeout: Duration,
    library: Library,
    mode: AbiMode,
) -> Result<(ExitStatus, String, String), AbiError> {
    cmd.stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    // SAFETY: the closure runs in the child between fork and exec and only calls prctl,
    // which is async-signal-safe; it allocates nothing and touches no lock.
    unsafe {
        cmd.pre_exec(|| {
            libc::prctl(libc::PR_SET_PDEATHSIG, libc::SIGKILL);
            Ok(())
        });
    }
    let spawn_error = |e: std::io::Error| AbiError::Io {
        what: format!("cannot start the {mode} run on {library}"),
        reason: e.to_string(),
    };
    let mut child = Reaped(cmd.spawn().map_err(spawn_error)?);
    let read = |pipe: Option<Box<dyn Read + Send>>| {
        std::thread::spawn(move || {
            let mut text = Vec::new();
            if let Some(mut pipe) = pipe {
                // A read error ends the text; the exit status tells what happened.
                let _ = pipe.read_to_end(&mut text);
            }
            String::from_utf8_lossy(&text).into_owned()
        })
    };
    let stdout = read(child.0.stdout.take().map(|p| Box::new(p) as _));
    let stderr = read(child.0.stderr.take().map(|p| Box::new(p) as _));
    let start = Instant::now();
    let status = loop {
        match child.0.try_wait() {
            Ok(Some(status)) => break status,
            Ok(None) if start.elapsed() >= timeout => {
                drop(child); // kills and reaps it, which closes the pipes
                let stderr = stderr.join().unwrap_or_default();
                return Err(AbiError::Timeout {
                    library,
                    mode,
                    seconds: timeout.as_secs(),
                    stderr: stderr.trim().to_string(),
                });
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(5)),
            Err(e) => {
                return Err(AbiError::Io {
                    what: format!("cannot wait for the {mode} run on {library}"),
                    reason: e.to_string(),
                })
            }
        }
    };
    let text = |h: std::thread::JoinHandle<String>| h.join().unwrap_or_default();
    Ok((status, text(stdout), text(stderr)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_missing_header_or_library_names_the_package() {
        let header = compile_error(
            "cc",
            "abi_bench.c:29:10: fatal error: GL/osmesa.h: No such file or directory",
        );
        assert!(matches!(header, AbiError::HeaderMissing { .. }), "{header}");
        let text = header.to_string();
        assert!(
            text.contains("gcc") && text.contains("libosmesa6-dev"),
            "{text}"
        );
        let link = compile_error("cc", "/usr/bin/ld: cannot find -lOSMesa: No such file");
        assert!(matches!(link, AbiError::HeaderMissing { .. }), "{link}");
        let other = compile_error("cc", "abi_bench.c:1:1: error: expected ';'");
        assert!(matches!(other, AbiError::Compile { .. }), "{other}");
    }

    #[test]
    fn the_loader_missing_mesa_names_libosmesa6() {
        let status = std::process::Command::new("false")
            .status()
            .expect("false runs");
        let loader = "./abi_bench: error while loading shared libraries: libOSMesa.so.8: \
                      cannot open shared object file: No such file or directory"
            .to_string();
        let mesa = run_error(Library::Mesa, AbiMode::Arrays, status, loader.clone());
        let text = mesa.to_string();
        assert!(matches!(mesa, AbiError::MesaMissing { .. }), "{text}");
        assert!(
            text.contains("libosmesa6") && text.contains("25.1"),
            "{text}"
        );
        let ours = run_error(Library::Fixedfunc, AbiMode::Arrays, status, loader);
        assert!(matches!(ours, AbiError::Failed { .. }), "{ours}");
    }

    #[test]
    fn a_child_over_its_time_is_killed_and_reaped() {
        let mut cmd = Command::new("sleep");
        cmd.arg("30");
        let start = Instant::now();
        let error = run_child(
            cmd,
            Duration::from_millis(200),
            Library::Mesa,
            AbiMode::Shadow,
        )
        .expect_err("sleep 30 outlives 200 ms");
        assert!(matches!(error, AbiError::Timeout { .. }), "{error}");
        assert!(start.elapsed() < Duration::from_secs(10));
    }
}
