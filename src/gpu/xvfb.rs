//! A private X server for the window backend on machines with no display: `Xvfb :N` on the
//! first free display number, stopped when the guard drops. `DISPLAY` is set for this
//! process so that winit and glutin find it.

use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use super::GpuError;

/// A running Xvfb, killed on drop.
pub struct VirtualDisplay {
    child: Child,
    display: String,
}

impl VirtualDisplay {
    /// Starts Xvfb and points `DISPLAY` at it. Call before any other thread reads the
    /// environment (at the start of `main`, or of the one window test).
    pub fn start() -> Result<VirtualDisplay, GpuError> {
        let number = (90..200)
            .find(|n| {
                !Path::new(&format!("/tmp/.X11-unix/X{n}")).exists()
                    && !Path::new(&format!("/tmp/.X{n}-lock")).exists()
            })
            .ok_or(GpuError::Window {
                detail: "no free X display number between :90 and :199".into(),
            })?;
        let display = format!(":{number}");
        let child = Command::new("Xvfb")
            .args([
                display.as_str(),
                "-screen",
                "0",
                "1024x768x24",
                "-nolisten",
                "tcp",
            ])
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .map_err(|e| GpuError::Window {
                detail: format!(
                    "no X display and Xvfb cannot start ({e}): apt-get install xvfb, \
                     or set DISPLAY"
                ),
            })?;
        let mut guard = VirtualDisplay { child, display };
        let socket = format!("/tmp/.X11-unix/X{number}");
        let start = Instant::now();
        while !Path::new(&socket).exists() {
            if start.elapsed() > Duration::from_secs(10) {
                return Err(GpuError::Window {
                    detail: format!("Xvfb {} did not come up within 10 s", guard.display),
                });
            }
            if let Ok(Some(status)) = guard.child.try_wait() {
                return Err(GpuError::Window {
                    detail: format!("Xvfb {} exited: {status}", guard.display),
                });
            }
            std::thread::sleep(Duration::from_millis(20));
        }
        std::env::set_var("DISPLAY", &guard.display);
        Ok(guard)
    }

    /// Starts Xvfb only when `DISPLAY` is unset; `None` means a display was already there.
    pub fn start_if_needed() -> Result<Option<VirtualDisplay>, GpuError> {
        if std::env::var_os("DISPLAY").is_some() {
            Ok(None)
        } else {
            VirtualDisplay::start().map(Some)
        }
    }

    pub fn display(&self) -> &str {
        &self.display
    }
}

impl Drop for VirtualDisplay {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}
