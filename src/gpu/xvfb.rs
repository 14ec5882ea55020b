//! A private X server for the window backend on machines with no display: `Xvfb :N` on the
//! first free display number, stopped when the last guard drops. `DISPLAY` is set for this
//! process so that winit and glutin find it, and put back when the server stops.
//!
//! **Stopped, not killed, on every exit path.** SIGTERM lets Xvfb remove its lock file
//! `/tmp/.XN-lock` and its socket `/tmp/.X11-unix/XN`; SIGKILL leaves both behind, and each
//! leak takes one display number until someone deletes them by hand. So the guard's drop
//! (normal return, error, panic) sends SIGTERM and waits up to [`STOP_WAIT`]; only a
//! server that ignores it is killed, and then its lock file and socket are removed here. A
//! process killed by a signal runs no destructors: the pid of every running server is kept
//! in [`RUNNING`], and the CLI's signal handler calls [`stop_private_displays`] (atomics,
//! `kill`, `waitpid`, `nanosleep`: async-signal-safe) before it dies.
//!
//! **Shared.** Several sessions in one process (a `compare` on the window backend holds
//! them all open) share the one server through [`VirtualDisplay::start_if_needed`]; it stops
//! when the last of them drops, not under the others.
//!
//! **Its stderr is kept**: a thread drains the pipe and keeps the last [`LOG_KEEP`] bytes,
//! shown when the server fails to start.

use std::ffi::OsString;
use std::io::Read;
use std::os::unix::process::CommandExt;
use std::path::PathBuf;
use std::process::{Child, Command, Stdio};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex, Weak};
use std::time::{Duration, Instant};

use super::GpuError;

/// How long a server is given to exit after SIGTERM before it is killed.
pub const STOP_WAIT: Duration = Duration::from_secs(3);
/// How long a server is given to open its socket.
const START_WAIT: Duration = Duration::from_secs(10);
/// How much of the server's stderr is kept (the end of it).
const LOG_KEEP: usize = 8 * 1024;
/// Display numbers tried.
const NUMBERS: std::ops::Range<u32> = 90..200;

/// The servers this process started and has not stopped, as `pid << 32 | display number`
/// (0: a free slot), for [`stop_private_displays`]. Atomics, so that a signal handler may
/// read them.
static RUNNING: [AtomicU64; 8] = [const { AtomicU64::new(0) }; 8];

/// The server `start_if_needed` hands out, while one runs.
static SHARED: Mutex<Weak<Running>> = Mutex::new(Weak::new());

fn remember(pid: i32, number: u32) {
    let entry = (pid as u64) << 32 | u64::from(number);
    for slot in &RUNNING {
        if slot
            .compare_exchange(0, entry, Ordering::SeqCst, Ordering::SeqCst)
            .is_ok()
        {
            return;
        }
    }
}

fn forget(pid: i32) {
    for slot in &RUNNING {
        let entry = slot.load(Ordering::SeqCst);
        if entry >> 32 == pid as u64 {
            let _ = slot.compare_exchange(entry, 0, Ordering::SeqCst, Ordering::SeqCst);
        }
    }
}

/// `PREFIX N SUFFIX` as a NUL-terminated path in `buf`, without allocating.
fn c_path<'a>(buf: &'a mut [u8; 48], prefix: &[u8], number: u32, suffix: &[u8]) -> &'a [u8] {
    let mut digits = [0u8; 10];
    let (mut n, mut k) = (number, 0);
    loop {
        digits[k] = b'0' + (n % 10) as u8;
        k += 1;
        n /= 10;
        if n == 0 {
            break;
        }
    }
    let mut len = 0;
    let mut put = |b: u8| {
        buf[len] = b;
        len += 1;
    };
    prefix.iter().for_each(|&b| put(b));
    digits[..k].iter().rev().for_each(|&b| put(b));
    suffix.iter().for_each(|&b| put(b));
    put(0);
    &buf[..len]
}

/// Removes the lock file and socket of display `number` when the lock file names `pid`
/// (a server that died before it could clean up): `open`, `read`, `unlink` only, for
/// [`stop_private_displays`].
fn remove_leftovers_in_handler(pid: i32, number: u32) {
    let mut lock = [0u8; 48];
    let lock = c_path(&mut lock, b"/tmp/.X", number, b"-lock");
    let mut text = [0u8; 32];
    // SAFETY: `lock` is NUL-terminated; `text` is a local buffer of the length given.
    let read = unsafe {
        let fd = libc::open(lock.as_ptr().cast(), libc::O_RDONLY);
        if fd < 0 {
            return;
        }
        let n = libc::read(fd, text.as_mut_ptr().cast(), text.len());
        libc::close(fd);
        n
    };
    let mut owner: i64 = 0;
    for &b in &text[..read.max(0) as usize] {
        if b.is_ascii_digit() {
            owner = owner * 10 + i64::from(b - b'0');
        }
    }
    if owner == i64::from(pid) {
        let mut socket = [0u8; 48];
        let socket = c_path(&mut socket, b"/tmp/.X11-unix/X", number, b"");
        // SAFETY: both paths are NUL-terminated.
        unsafe {
            libc::unlink(socket.as_ptr().cast());
            libc::unlink(lock.as_ptr().cast());
        }
    }
}

/// Set when a signal is ending the process (see [`mark_ending`]).
static ENDING: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// Says that a signal is ending the process: a window's X connection that breaks from now
/// on broke because [`stop_private_displays`] stopped its server, and the thread that
/// notices waits for the signal to end the process instead of exiting with Xlib's status 1.
/// Async-signal-safe (an atomic store).
pub fn mark_ending() {
    ENDING.store(true, Ordering::SeqCst);
}

/// Whether [`mark_ending`] was called.
pub fn ending() -> bool {
    ENDING.load(Ordering::SeqCst)
}

/// Waits for the signal [`mark_ending`] announced to end the process (its handler
/// re-raises it once the servers are stopped): for a thread whose work failed because its
/// server was stopped under it, which must not exit with a status of its own first.
pub fn await_ending_signal() -> ! {
    loop {
        // SAFETY: pause has no preconditions; the pending signal ends the process.
        unsafe { libc::pause() };
    }
}

/// Stops every X server this process started: SIGTERM, a wait of up to [`STOP_WAIT`] for it
/// to exit, SIGKILL after that; then removes its lock file and socket if it could not (it
/// was killed, or SIGTERM came before it set up its own handler). For signal handlers: it
/// allocates nothing, takes no lock and calls only async-signal-safe functions (`kill`,
/// `waitpid`, `nanosleep`, `open`, `read`, `close`, `unlink`). A server stopped here is
/// reaped here; its guard's drop then finds it gone.
pub fn stop_private_displays() {
    for slot in &RUNNING {
        let entry = slot.swap(0, Ordering::SeqCst);
        let (pid, number) = ((entry >> 32) as i32, entry as u32);
        if pid <= 0 {
            continue;
        }
        // SAFETY: plain system calls on a child's pid; `status` is a local.
        unsafe {
            libc::kill(pid, libc::SIGTERM);
            let mut status = 0;
            let pause = libc::timespec {
                tv_sec: 0,
                tv_nsec: 10_000_000,
            };
            let tries = STOP_WAIT.as_millis() / 10;
            let mut gone = false;
            for _ in 0..tries {
                if libc::waitpid(pid, &mut status, libc::WNOHANG) != 0 {
                    gone = true;
                    break;
                }
                libc::nanosleep(&pause, std::ptr::null_mut());
            }
            if !gone {
                libc::kill(pid, libc::SIGKILL);
                libc::waitpid(pid, &mut status, 0);
            }
        }
        remove_leftovers_in_handler(pid, number);
    }
}

/// Blocks SIGINT, SIGTERM, SIGHUP and SIGPIPE in this thread until dropped (a pending one
/// is delivered then).
struct BlockEndingSignals(libc::sigset_t);

impl BlockEndingSignals {
    fn new() -> BlockEndingSignals {
        // SAFETY: the sets are initialised by sigemptyset before use.
        unsafe {
            let mut set: libc::sigset_t = std::mem::zeroed();
            let mut old: libc::sigset_t = std::mem::zeroed();
            libc::sigemptyset(&mut set);
            for signal in [libc::SIGINT, libc::SIGTERM, libc::SIGHUP, libc::SIGPIPE] {
                libc::sigaddset(&mut set, signal);
            }
            libc::pthread_sigmask(libc::SIG_BLOCK, &set, &mut old);
            BlockEndingSignals(old)
        }
    }
}

impl Drop for BlockEndingSignals {
    fn drop(&mut self) {
        // SAFETY: restores the mask saved by `new`.
        unsafe {
            libc::pthread_sigmask(libc::SIG_SETMASK, &self.0, std::ptr::null_mut());
        }
    }
}

/// A running Xvfb, stopped when the last clone of its guard drops.
#[derive(Clone)]
pub struct VirtualDisplay {
    running: Arc<Running>,
}

struct Running {
    child: Child,
    number: u32,
    display: String,
    log: Arc<Mutex<Vec<u8>>>,
    /// `DISPLAY` before the server was started, put back when it stops.
    previous: Option<OsString>,
}

fn lock_file(number: u32) -> PathBuf {
    PathBuf::from(format!("/tmp/.X{number}-lock"))
}

fn socket(number: u32) -> PathBuf {
    PathBuf::from(format!("/tmp/.X11-unix/X{number}"))
}

/// The pid written in a display's lock file.
fn lock_owner(number: u32) -> Option<i32> {
    std::fs::read_to_string(lock_file(number))
        .ok()?
        .trim()
        .parse()
        .ok()
}

/// Drains `from` into `log` on a thread, keeping the last [`LOG_KEEP`] bytes.
fn keep_log(mut from: impl Read + Send + 'static) -> Arc<Mutex<Vec<u8>>> {
    let log = Arc::new(Mutex::new(Vec::new()));
    let into = Arc::clone(&log);
    std::thread::spawn(move || {
        let mut buf = [0u8; 1024];
        while let Ok(n @ 1..) = from.read(&mut buf) {
            let mut log = into.lock().unwrap_or_else(|e| e.into_inner());
            log.extend_from_slice(&buf[..n]);
            let excess = log.len().saturating_sub(LOG_KEEP);
            log.drain(..excess);
        }
    });
    log
}

/// Why starting on one display number failed.
enum Attempt {
    /// Another server took the number between the check and the start: try the next.
    Taken,
    Failed(GpuError),
}

impl VirtualDisplay {
    /// Starts Xvfb and points `DISPLAY` at it. Call before any other thread reads the
    /// environment (at the start of `main`, or of the one window test).
    pub fn start() -> Result<VirtualDisplay, GpuError> {
        let mut numbers = NUMBERS.filter(|&n| !socket(n).exists() && !lock_file(n).exists());
        loop {
            let number = numbers.next().ok_or_else(|| GpuError::Window {
                detail: format!(
                    "no free X display number between :{} and :{}",
                    NUMBERS.start,
                    NUMBERS.end - 1
                ),
            })?;
            match VirtualDisplay::start_on(number) {
                Ok(display) => return Ok(display),
                Err(Attempt::Taken) => continue,
                Err(Attempt::Failed(e)) => return Err(e),
            }
        }
    }

    fn start_on(number: u32) -> Result<VirtualDisplay, Attempt> {
        let display = format!(":{number}");
        // Signals that end the process wait until the server is in `RUNNING`, so that the
        // handler stops it even when one comes while the server starts up (this thread's
        // mask; the child's is emptied before exec, or Xvfb would not hear SIGTERM).
        let blocked = BlockEndingSignals::new();
        let mut command = Command::new("Xvfb");
        // SAFETY: the closure calls only sigemptyset and sigprocmask, async-signal-safe.
        unsafe {
            command.pre_exec(|| {
                let mut empty: libc::sigset_t = std::mem::zeroed();
                libc::sigemptyset(&mut empty);
                libc::sigprocmask(libc::SIG_SETMASK, &empty, std::ptr::null_mut());
                Ok(())
            });
        }
        let child = command
            .args([
                display.as_str(),
                "-screen",
                "0",
                "1024x768x24",
                "-nolisten",
                "tcp",
            ])
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .map_err(|e| {
                Attempt::Failed(GpuError::Window {
                    detail: format!(
                        "no X display and Xvfb cannot start ({e}): apt-get install xvfb, \
                         or set DISPLAY"
                    ),
                })
            });
        let mut child = child?;
        let pid = child.id() as i32;
        remember(pid, number);
        drop(blocked);
        // Cannot fail: the command above sets stderr to Stdio::piped(), and this is the one
        // take() of it.
        let log = keep_log(child.stderr.take().expect("stderr is piped"));
        let running = Running {
            child,
            number,
            display,
            log,
            previous: std::env::var_os("DISPLAY"),
        };
        let mut guard = VirtualDisplay {
            running: Arc::new(running),
        };
        let start = Instant::now();
        // Up when the server owns the number (its pid in the lock file: another process
        // may have started a server on the same number at the same moment, and the socket
        // alone would be that server's) and listens on its socket.
        while !(lock_owner(number) == Some(pid) && socket(number).exists()) {
            // Cannot fail: `guard` was made above and no clone of its Arc exists before this
            // loop returns it.
            let running = Arc::get_mut(&mut guard.running).expect("not shared yet");
            if let Ok(Some(status)) = running.child.try_wait() {
                forget(pid);
                let said = running.said();
                // Another server has the number (or had it a moment ago: it may be gone
                // already, with its lock file).
                if lock_owner(number).is_some_and(|owner| owner != pid)
                    || said.contains("Server is already active")
                {
                    return Err(Attempt::Taken);
                }
                return Err(Attempt::Failed(GpuError::Window {
                    detail: format!("Xvfb {} exited ({status}){said}", running.display),
                }));
            }
            if start.elapsed() > START_WAIT {
                let display = running.display.clone();
                drop(guard);
                return Err(Attempt::Failed(GpuError::Window {
                    detail: format!(
                        "Xvfb {display} did not come up within {} s",
                        START_WAIT.as_secs()
                    ),
                }));
            }
            std::thread::sleep(Duration::from_millis(20));
        }
        std::env::set_var("DISPLAY", &guard.running.display);
        Ok(guard)
    }

    /// Starts Xvfb only when `DISPLAY` is unset; `None` means a display was already there.
    /// When `DISPLAY` names a server this process started, that server is shared.
    pub fn start_if_needed() -> Result<Option<VirtualDisplay>, GpuError> {
        let mut shared = SHARED.lock().unwrap_or_else(|e| e.into_inner());
        let current = std::env::var_os("DISPLAY");
        if let Some(running) = shared.upgrade() {
            if current.as_deref() == Some(running.display.as_ref()) {
                return Ok(Some(VirtualDisplay { running }));
            }
        }
        if current.is_some() {
            return Ok(None);
        }
        let display = VirtualDisplay::start()?;
        *shared = Arc::downgrade(&display.running);
        Ok(Some(display))
    }

    /// `:N`.
    pub fn display(&self) -> &str {
        &self.running.display
    }

    /// The server's process id.
    pub fn pid(&self) -> u32 {
        self.running.child.id()
    }
}

impl Running {
    /// The end of what the server wrote to stderr, as a suffix for a message.
    fn said(&self) -> String {
        // The pipe closes when the server exits; give the thread a moment to read the end.
        std::thread::sleep(Duration::from_millis(50));
        let log = self.log.lock().unwrap_or_else(|e| e.into_inner());
        let text = String::from_utf8_lossy(&log);
        let text = text.trim();
        if text.is_empty() {
            String::new()
        } else {
            format!("; it said:\n{text}")
        }
    }

    /// `DISPLAY` as it was before the server started, if it still names the server.
    fn put_display_back(&self) {
        if std::env::var_os("DISPLAY").as_deref() == Some(self.display.as_ref()) {
            match &self.previous {
                Some(previous) => std::env::set_var("DISPLAY", previous),
                None => std::env::remove_var("DISPLAY"),
            }
        }
    }

    /// Removes the lock file and socket of a server that could not clean up after itself
    /// (only when the lock file still names it).
    fn remove_leftovers(&self, pid: i32) {
        if lock_owner(self.number) == Some(pid) {
            let _ = std::fs::remove_file(socket(self.number));
            let _ = std::fs::remove_file(lock_file(self.number));
        }
    }
}

impl Drop for Running {
    fn drop(&mut self) {
        let pid = self.child.id() as i32;
        // Out of the signal handler's list first: from here on only this drop stops it.
        forget(pid);
        if !matches!(self.child.try_wait(), Ok(None)) {
            // It exited already (and was reaped): its pid may now be another process's.
            self.remove_leftovers(pid);
            self.put_display_back();
            return;
        }
        // SAFETY: a signal to our own child, which has not been reaped.
        unsafe {
            libc::kill(pid, libc::SIGTERM);
        }
        let deadline = Instant::now() + STOP_WAIT;
        let exited = loop {
            match self.child.try_wait() {
                // Err: already reaped (by `stop_private_displays`).
                Ok(Some(_)) | Err(_) => break true,
                Ok(None) if Instant::now() >= deadline => break false,
                Ok(None) => std::thread::sleep(Duration::from_millis(5)),
            }
        };
        if !exited {
            let _ = self.child.kill();
            let _ = self.child.wait();
        }
        self.remove_leftovers(pid);
        self.put_display_back();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_for_the_signal_handler_are_built_without_allocating() {
        let mut buf = [0u8; 48];
        assert_eq!(
            c_path(&mut buf, b"/tmp/.X", 123, b"-lock"),
            b"/tmp/.X123-lock\0"
        );
        let mut buf = [0u8; 48];
        assert_eq!(
            c_path(&mut buf, b"/tmp/.X11-unix/X", 0, b""),
            b"/tmp/.X11-unix/X0\0"
        );
    }
}
