//! Writing files so that nothing is lost and nothing is silently wrong: every byte written
//! is checked, every file is flushed to the disk before it counts as written, and a file
//! appears under its name only when it is complete.
//!
//! **Atomic.** A regular file is written to a temporary name in the same folder
//! (`.NAME.PID-N.tmp`), synced (`fsync`: a full disk or a failing device is reported here,
//! not lost in the page cache), and renamed over NAME: a reader sees the old file or the
//! new one, never a part of either. A failed write removes its temporary file and leaves
//! NAME as it was. A path that exists and is not a regular file (`/dev/stdout`,
//! `/dev/full`, a FIFO) is written in place — a rename would replace the device — and its
//! failures are reported the same way.
//!
//! **Checked before the work.** [`check_output`] refuses, before anything is rendered, a
//! path that cannot be written: a folder, a read-only file, a parent folder that cannot be
//! made or written, a file name that is not `.png` where a PNG goes. [`same_file`] tells
//! when two output options name one file.
//!
//! **PNG is encoded in memory** and then written, so a failed encode leaves no file behind.

use std::fs;
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

use super::ReportError;

/// Distinguishes the temporary files of one process.
static TEMPORARY: AtomicU64 = AtomicU64::new(0);

/// The folder a path's file lives in (`.` for a bare name).
fn parent_of(path: &Path) -> &Path {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    }
}

/// A fresh temporary name beside `path`.
fn temporary_beside(path: &Path, what: &str) -> PathBuf {
    let name = path
        .file_name()
        .map_or("file".into(), |n| n.to_string_lossy());
    let n = TEMPORARY.fetch_add(1, Ordering::Relaxed);
    parent_of(path).join(format!(".{name}.{}-{n}.{what}", std::process::id()))
}

fn write_error(path: &Path) -> impl Fn(io::Error) -> ReportError + '_ {
    move |source| ReportError::Write {
        path: path.to_path_buf(),
        source,
    }
}

/// Writes `bytes` to `path` as the module note says: atomically for a regular file (or a
/// new one), in place for a device; flushed and checked either way.
pub fn write_file(path: &Path, bytes: &[u8]) -> Result<(), ReportError> {
    let err = write_error(path);
    // Write through a symbolic link to the file it names, as `cp` does.
    let target = match fs::symlink_metadata(path) {
        Ok(m) if m.file_type().is_symlink() => fs::canonicalize(path).map_err(&err)?,
        _ => path.to_path_buf(),
    };
    match fs::metadata(&target) {
        Ok(m) if m.is_dir() => return Err(ReportError::IsFolder { path: target }),
        Ok(m) if !m.is_file() => {
            let mut file = fs::OpenOptions::new()
                .write(true)
                .open(&target)
                .map_err(&err)?;
            file.write_all(bytes).map_err(&err)?;
            return file.flush().map_err(&err);
        }
        _ => {}
    }
    let temporary = temporary_beside(&target, "tmp");
    let written = (|| -> io::Result<()> {
        let mut file = fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&temporary)?;
        file.write_all(bytes)?;
        file.flush()?;
        if let Ok(old) = fs::metadata(&target) {
            file.set_permissions(old.permissions())?;
        }
        file.sync_all()?;
        drop(file);
        fs::rename(&temporary, &target)
    })();
    if let Err(e) = written {
        let _ = fs::remove_file(&temporary);
        return Err(err(e));
    }
    Ok(())
}

/// The PNG file of an image, in memory.
pub fn png_bytes<P, C>(image: &image::ImageBuffer<P, C>) -> Result<Vec<u8>, image::ImageError>
where
    P: image::PixelWithColorType,
    [P::Subpixel]: image::EncodableLayout,
    C: std::ops::Deref<Target = [P::Subpixel]>,
{
    let mut bytes = io::Cursor::new(Vec::new());
    image.write_to(&mut bytes, image::ImageFormat::Png)?;
    Ok(bytes.into_inner())
}

/// Encodes `image` as PNG and writes it to `path` ([`write_file`]). A name with another
/// extension is refused: the file would not be what its name says.
pub fn save_png<P, C>(image: &image::ImageBuffer<P, C>, path: &Path) -> Result<(), ReportError>
where
    P: image::PixelWithColorType,
    [P::Subpixel]: image::EncodableLayout,
    C: std::ops::Deref<Target = [P::Subpixel]>,
{
    check_png_name(path)?;
    let bytes = png_bytes(image).map_err(|source| ReportError::Image {
        path: path.to_path_buf(),
        source,
    })?;
    write_file(path, &bytes)
}

/// Refuses a file name whose extension is not `.png` (no extension is accepted: devices
/// such as `/dev/stdout` have none).
pub fn check_png_name(path: &Path) -> Result<(), ReportError> {
    match path.extension() {
        Some(e) if !e.eq_ignore_ascii_case("png") => Err(ReportError::NotPng {
            path: path.to_path_buf(),
        }),
        _ => Ok(()),
    }
}

/// Creates `dir` (and its parents) when missing, and proves that a file can be made in it
/// by making one and removing it. Permission bits alone do not say (root ignores them; a
/// read-only mount ignores them the other way).
pub fn check_output_dir(dir: &Path) -> Result<(), ReportError> {
    fs::create_dir_all(dir).map_err(|source| ReportError::CreateDir {
        path: dir.to_path_buf(),
        source,
    })?;
    let probe = temporary_beside(&dir.join("probe"), "probe");
    fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(&probe)
        .map_err(|source| ReportError::Write {
            path: dir.to_path_buf(),
            source,
        })?;
    let _ = fs::remove_file(&probe);
    Ok(())
}

/// Whether `path` can be written, checked before any work is done: it is not a folder
/// nor a read-only file, its folder exists (it is created when missing) and takes new
/// files; a device is opened for writing. Writes nothing to `path` itself.
pub fn check_output(path: &Path) -> Result<(), ReportError> {
    match fs::metadata(path) {
        Ok(m) if m.is_dir() => Err(ReportError::IsFolder {
            path: path.to_path_buf(),
        }),
        Ok(m) if m.is_file() && m.permissions().readonly() => Err(ReportError::ReadOnly {
            path: path.to_path_buf(),
        }),
        Ok(m) if !m.is_file() => fs::OpenOptions::new()
            .write(true)
            .open(path)
            .map(drop)
            .map_err(write_error(path)),
        _ => {
            // A regular file is replaced by a rename, so what matters is its folder.
            let real = fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf());
            check_output_dir(parent_of(&real))
        }
    }
}

/// The file a path names, as far as it can be known: the resolved path when it exists,
/// else its resolved folder joined with its name.
fn identity(path: &Path) -> PathBuf {
    if let Ok(real) = fs::canonicalize(path) {
        return real;
    }
    match (fs::canonicalize(parent_of(path)), path.file_name()) {
        (Ok(dir), Some(name)) => dir.join(name),
        _ => path.to_path_buf(),
    }
}

/// Whether `a` and `b` name the same file (through `..`, links, or hard links).
pub fn same_file(a: &Path, b: &Path) -> bool {
    use std::os::unix::fs::MetadataExt;
    if let (Ok(ma), Ok(mb)) = (fs::metadata(a), fs::metadata(b)) {
        if ma.dev() == mb.dev() && ma.ino() == mb.ino() {
            return true;
        }
    }
    identity(a) == identity(b)
}

/// Removes `path` if it is there (a page of an earlier run, removed before anything of the
/// new run is written, so the folder never shows one run's page over another's files).
pub fn remove_if_present(path: &Path) -> Result<(), ReportError> {
    match std::fs::remove_file(path) {
        Err(e) if e.kind() != std::io::ErrorKind::NotFound => Err(ReportError::Write {
            path: path.to_path_buf(),
            source: e,
        }),
        _ => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_write_replaces_the_file_whole_and_leaves_no_temporary_file() {
        let dir = tempfile::tempdir().expect("temp dir");
        let path = dir.path().join("a.csv");
        write_file(&path, b"old\n").expect("first write");
        write_file(&path, b"new\n").expect("second write");
        assert_eq!(fs::read(&path).expect("read"), b"new\n");
        let names: Vec<_> = fs::read_dir(dir.path())
            .expect("list")
            .map(|e| e.expect("entry").file_name())
            .collect();
        assert_eq!(names, vec![std::ffi::OsString::from("a.csv")]);
    }

    #[test]
    fn a_write_to_a_full_device_is_an_error() {
        let e = write_file(Path::new("/dev/full"), &[0u8; 100]).expect_err("/dev/full is full");
        assert!(e.to_string().contains("/dev/full"), "{e}");
    }

    #[test]
    fn a_failed_write_keeps_the_old_file() {
        let dir = tempfile::tempdir().expect("temp dir");
        let path = dir.path().join("keep.txt");
        fs::write(&path, "kept").expect("write");
        // A folder where the temporary file would go makes the write fail.
        let blocked = dir.path().join("missing").join("keep.txt");
        assert!(write_file(&blocked, b"x").is_err());
        assert_eq!(fs::read_to_string(&path).expect("read"), "kept");
    }

    #[test]
    fn output_checks_refuse_folders_other_extensions_and_unmakeable_folders() {
        let dir = tempfile::tempdir().expect("temp dir");
        assert!(matches!(
            check_output(dir.path()),
            Err(ReportError::IsFolder { .. })
        ));
        assert!(matches!(
            check_png_name(Path::new("x.jpg")),
            Err(ReportError::NotPng { .. })
        ));
        check_png_name(Path::new("x.PNG")).expect("PNG in capitals");
        check_png_name(Path::new("/dev/stdout")).expect("no extension");
        let file = dir.path().join("file");
        fs::write(&file, "").expect("write");
        assert!(matches!(
            check_output(&file.join("sub").join("out.png")),
            Err(ReportError::CreateDir { .. })
        ));
        let nested = dir.path().join("new").join("out.png");
        check_output(&nested).expect("a missing folder is made");
        assert!(dir.path().join("new").is_dir());
        assert!(!nested.exists(), "the check writes nothing under the name");
    }

    #[test]
    fn same_file_sees_through_dot_dot_and_links() {
        let dir = tempfile::tempdir().expect("temp dir");
        let a = dir.path().join("a.png");
        let via = dir.path().join("sub").join("..").join("a.png");
        fs::create_dir(dir.path().join("sub")).expect("mkdir");
        assert!(same_file(&a, &via));
        assert!(!same_file(&a, &dir.path().join("b.png")));
        fs::write(&a, "").expect("write");
        let link = dir.path().join("link.png");
        std::os::unix::fs::symlink(&a, &link).expect("symlink");
        assert!(same_file(&a, &link));
    }
}
