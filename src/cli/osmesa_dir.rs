//! `fixedfunc osmesa-dir`: a folder holding the C library under the name programs link
//! against, so that `LD_LIBRARY_PATH=$(fixedfunc osmesa-dir) ./legacy-program` runs an
//! unmodified OSMesa program on the layer.
//!
//! Cargo builds the library beside the binary as `libfixedfunc.so` (its soname is already
//! `libOSMesa.so.8`) — `cargo build` copies it there, `cargo test` leaves it in `deps/` —
//! and the folder is `osmesa/` beside them, with `libOSMesa.so.8` a link to the newer of
//! the two, made on the first call and checked on every call.

use std::path::{Path, PathBuf};

use super::error::CliError;

/// The library's file name as cargo writes it.
pub const LIBRARY: &str = "libfixedfunc.so";
/// The name programs load.
pub const SONAME: &str = "libOSMesa.so.8";

pub fn run() -> Result<(), CliError> {
    let exe = std::env::current_exe().map_err(|e| CliError::Osmesa(e.to_string()))?;
    let dir = exe
        .parent()
        .ok_or_else(|| CliError::Osmesa("the binary has no folder".into()))?;
    let folder = osmesa_folder(dir)?;
    outln!("{}", folder.display())?;
    Ok(())
}

/// `dir/osmesa`, holding `libOSMesa.so.8` → `../libfixedfunc.so` (or `../deps/…`).
pub fn osmesa_folder(dir: &Path) -> Result<PathBuf, CliError> {
    let modified = |p: &Path| std::fs::metadata(p).and_then(|m| m.modified()).ok();
    let candidates = [PathBuf::from(LIBRARY), Path::new("deps").join(LIBRARY)];
    let relative = candidates
        .iter()
        .filter_map(|c| modified(&dir.join(c)).map(|t| (t, c)))
        .max_by_key(|(t, _)| *t)
        .map(|(_, c)| c.clone())
        .ok_or_else(|| {
            CliError::Osmesa(format!(
                "{} is missing: build the library with `cargo build --release` (it is built \
                 with the binary)",
                dir.join(LIBRARY).display()
            ))
        })?;
    let folder = dir.join("osmesa");
    std::fs::create_dir_all(&folder)
        .map_err(|e| CliError::Osmesa(format!("cannot create {}: {e}", folder.display())))?;
    let link = folder.join(SONAME);
    let target = Path::new("..").join(relative);
    match std::fs::read_link(&link) {
        Ok(t) if t == target => {}
        Ok(_) | Err(_) => {
            // A stale link or file: replace it.
            let _ = std::fs::remove_file(&link);
            std::os::unix::fs::symlink(&target, &link)
                .map_err(|e| CliError::Osmesa(format!("cannot link {}: {e}", link.display())))?;
        }
    }
    Ok(folder)
}
