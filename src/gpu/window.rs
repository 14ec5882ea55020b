//! A real window on X11 through glutin + winit: GLX, or EGL on X11 when GLX fails.
//!
//! winit allows one event loop per process, so the loop lives in a thread-local and every
//! window context of a process must be created on the thread that made the first one (the
//! CLI's main thread; one test function in the window test binary).
//!
//! `present` blits a render target into the window's back buffer (same size, NEAREST, so
//! the copy is exact), swaps, and reads the front buffer back: what the window shows.
//! `show` does the same for a picture made on the CPU (uploaded to a texture first).
//!
//! `wait_input` pumps the event loop until something arrives or the timeout passes (`None`:
//! until an event or a [`Waker`]), and returns what the user did in [`Input`] terms: the
//! loop sleeps in the X connection, so a window waiting for input uses no CPU.

use std::cell::RefCell;
use std::num::NonZeroU32;
use std::time::{Duration, Instant};

use glow::HasContext;
use glutin::config::ConfigTemplateBuilder;
use glutin::context::{
    ContextApi, ContextAttributesBuilder, GlProfile, NotCurrentGlContext, PossiblyCurrentContext,
    PossiblyCurrentGlContext, Version,
};
use glutin::display::{GetGlDisplay, GlDisplay};
use glutin::surface::{GlSurface, Surface, WindowSurface};
use glutin_winit::{DisplayBuilder, GlWindow};
use raw_window_handle::HasWindowHandle;
use winit::application::ApplicationHandler;
use winit::dpi::PhysicalSize;
use winit::event::{ElementState, MouseButton, WindowEvent};
use winit::event_loop::{ActiveEventLoop, EventLoop};
use winit::keyboard::{Key, NamedKey};
use winit::platform::pump_events::EventLoopExtPumpEvents;
use winit::platform::x11::EventLoopBuilderExtX11;
use winit::window::{Window, WindowId};

use super::window_input::{Input, KeyName, Waker};
use super::{GpuError, Profile, RenderTarget};

const INITIAL_SIZE: (u32, u32) = (256, 256);

thread_local! {
    static EVENT_LOOP: RefCell<Option<EventLoop<()>>> = const { RefCell::new(None) };
}

/// Xlib's handler of a broken connection, as it was before ours.
static PREVIOUS_IO_HANDLER: std::sync::OnceLock<Option<IoErrorHandler>> =
    std::sync::OnceLock::new();

type IoErrorHandler = unsafe extern "C" fn(*mut std::ffi::c_void) -> std::ffi::c_int;

/// Xlib calls this when the X connection breaks (it exits the process if this returns).
/// While a signal ends the process (`xvfb::mark_ending`: the server was stopped by the
/// signal handler), wait for the re-raised signal; otherwise do what Xlib did.
unsafe extern "C" fn on_io_error(display: *mut std::ffi::c_void) -> std::ffi::c_int {
    if super::xvfb::ending() {
        super::xvfb::await_ending_signal();
    }
    match PREVIOUS_IO_HANDLER.get().copied().flatten() {
        // SAFETY: the handler Xlib had, called as Xlib would have.
        Some(previous) => unsafe { previous(display) },
        None => {
            eprintln!("fixedfunc: the connection to the X server broke");
            // SAFETY: ends the process, as Xlib's own handler does.
            unsafe { libc::_exit(1) }
        }
    }
}

/// Installs [`on_io_error`] in the process's Xlib (loaded by the window system already).
fn install_io_error_handler() {
    PREVIOUS_IO_HANDLER.get_or_init(|| {
        type Set = unsafe extern "C" fn(Option<IoErrorHandler>) -> Option<IoErrorHandler>;
        // SAFETY: libX11 is the library winit and GLX use; XSetIOErrorHandler takes and
        // returns a handler pointer. The library stays loaded (forgotten below).
        unsafe {
            let lib = libloading::Library::new("libX11.so.6").ok()?;
            let set = lib.get::<Set>(b"XSetIOErrorHandler\0").ok()?;
            let previous = set(Some(on_io_error));
            std::mem::forget(lib);
            previous
        }
    });
}

fn window_err(what: &str) -> impl Fn(Box<dyn std::error::Error>) -> GpuError + '_ {
    move |e| GpuError::Window {
        detail: format!("{what}: {e}"),
    }
}

/// Events are only pumped so that the X server maps and resizes the window; none is acted on.
struct Ignore;

impl ApplicationHandler for Ignore {
    fn resumed(&mut self, _: &ActiveEventLoop) {}
    fn window_event(&mut self, _: &ActiveEventLoop, _: WindowId, _: WindowEvent) {}
}

fn pump(event_loop: &mut EventLoop<()>, time: Duration) {
    let _ = event_loop.pump_app_events(Some(time), &mut Ignore);
}

/// Collects what the user does to the window into [`Input`]s.
#[derive(Default)]
struct Collect {
    inputs: Vec<Input>,
    shift: bool,
    dragging: bool,
    cursor: Option<(f64, f64)>,
}

impl ApplicationHandler for Collect {
    fn resumed(&mut self, _: &ActiveEventLoop) {}

    fn user_event(&mut self, _: &ActiveEventLoop, (): ()) {}

    fn window_event(&mut self, _: &ActiveEventLoop, _: WindowId, event: WindowEvent) {
        match event {
            WindowEvent::CloseRequested | WindowEvent::Destroyed => self.inputs.push(Input::Closed),
            WindowEvent::RedrawRequested => self.inputs.push(Input::Exposed),
            WindowEvent::ModifiersChanged(m) => self.shift = m.state().shift_key(),
            WindowEvent::KeyboardInput { event, .. } if event.state == ElementState::Pressed => {
                let key = match event.logical_key {
                    Key::Named(NamedKey::ArrowLeft) => Some(KeyName::Left),
                    Key::Named(NamedKey::ArrowRight) => Some(KeyName::Right),
                    Key::Named(NamedKey::ArrowUp) => Some(KeyName::Up),
                    Key::Named(NamedKey::ArrowDown) => Some(KeyName::Down),
                    Key::Named(NamedKey::Escape) => Some(KeyName::Escape),
                    Key::Character(text) => text.chars().next().map(KeyName::Char),
                    _ => None,
                };
                if let Some(key) = key {
                    self.inputs.push(Input::Key {
                        key,
                        shift: self.shift,
                    });
                }
            }
            WindowEvent::MouseInput {
                state,
                button: MouseButton::Left,
                ..
            } => self.dragging = state == ElementState::Pressed,
            WindowEvent::CursorMoved { position, .. } => {
                let now = (position.x, position.y);
                if let (true, Some(before)) = (self.dragging, self.cursor) {
                    self.inputs.push(Input::Drag {
                        dx: now.0 - before.0,
                        dy: now.1 - before.1,
                        shift: self.shift,
                    });
                }
                self.cursor = Some(now);
            }
            _ => {}
        }
    }
}

pub struct WindowContext {
    // Drop order: context and surface before the window they render into.
    context: PossiblyCurrentContext,
    surface: Surface<WindowSurface>,
    window: Window,
    api: String,
    /// The modifier and button state between two waits for input.
    collect: Collect,
}

impl WindowContext {
    pub fn create(profile: Profile) -> Result<(WindowContext, glow::Context), GpuError> {
        if std::env::var_os("DISPLAY").is_none() {
            return Err(GpuError::Window {
                detail: "no X display: set DISPLAY, or run under xvfb-run \
                         (apt-get install xvfb xauth)"
                    .into(),
            });
        }
        EVENT_LOOP.with(|cell| {
            let mut slot = cell.borrow_mut();
            if slot.is_none() {
                let event_loop = EventLoop::builder()
                    .with_x11()
                    .with_any_thread(true)
                    .build()
                    .map_err(|e| GpuError::Window {
                        detail: format!(
                            "cannot open the X11 event loop: {e} (winit allows one event loop \
                             per process: create every window context on one thread)"
                        ),
                    })?;
                *slot = Some(event_loop);
            }
            let event_loop = slot.as_mut().ok_or(GpuError::Window {
                detail: "event loop missing".into(),
            })?;
            Self::create_on(event_loop, profile)
        })
    }

    fn create_on(
        event_loop: &mut EventLoop<()>,
        profile: Profile,
    ) -> Result<(WindowContext, glow::Context), GpuError> {
        let attributes = Window::default_attributes()
            .with_title("fixedfunc")
            .with_inner_size(PhysicalSize::new(INITIAL_SIZE.0, INITIAL_SIZE.1))
            .with_resizable(true);
        let (window, config) = DisplayBuilder::new()
            .with_window_attributes(Some(attributes))
            .build(
                &*event_loop,
                ConfigTemplateBuilder::new().with_alpha_size(8),
                |mut configs| {
                    // Cannot fail: glutin reports "no config" as the build's error and calls
                    // the picker only with at least one config.
                    configs.next().expect("glutin passes at least one config")
                },
            )
            .map_err(window_err("no GL config for an X11 window"))?;
        let window = window.ok_or(GpuError::Window {
            detail: "glutin created no window".into(),
        })?;
        let handle = window
            .window_handle()
            .map_err(|e| GpuError::Window {
                detail: format!("window handle: {e}"),
            })?
            .as_raw();
        let display = config.display();
        let attributes = match profile {
            Profile::Core33 => ContextAttributesBuilder::new()
                .with_profile(GlProfile::Core)
                .with_context_api(ContextApi::OpenGl(Some(Version::new(3, 3)))),
            Profile::Compatibility => ContextAttributesBuilder::new()
                .with_profile(GlProfile::Compatibility)
                .with_context_api(ContextApi::OpenGl(None)),
        }
        .build(Some(handle));
        // SAFETY: the handle belongs to `window`, which outlives the context.
        let context = unsafe { display.create_context(&config, &attributes) }.map_err(|e| {
            GpuError::Window {
                detail: format!("{} context: {e}", profile.name()),
            }
        })?;
        let surface_attributes = window
            .build_surface_attributes(Default::default())
            .map_err(|e| GpuError::Window {
                detail: format!("surface attributes: {e}"),
            })?;
        // SAFETY: as above, the window outlives the surface.
        let surface = unsafe { display.create_window_surface(&config, &surface_attributes) }
            .map_err(|e| GpuError::Window {
                detail: format!("window surface: {e}"),
            })?;
        let context = context
            .make_current(&surface)
            .map_err(|e| GpuError::Window {
                detail: format!("make current: {e}"),
            })?;
        let api = format!("{} on X11 (glutin + winit)", display.version_string());
        install_io_error_handler();
        window.set_visible(true);
        pump(event_loop, Duration::from_millis(10));
        // SAFETY: the context is current; the display resolves its entry points.
        let gl = unsafe {
            glow::Context::from_loader_function_cstr(|name| display.get_proc_address(name))
        };
        Ok((
            WindowContext {
                context,
                surface,
                window,
                api,
                collect: Collect::default(),
            },
            gl,
        ))
    }

    pub fn proc_address(&self, name: &str) -> *const std::ffi::c_void {
        match std::ffi::CString::new(name) {
            Ok(c) => self.context.display().get_proc_address(&c),
            Err(_) => std::ptr::null(),
        }
    }

    pub fn describe(&self) -> String {
        self.api.clone()
    }

    pub fn make_current(&self) -> Result<(), GpuError> {
        self.context
            .make_current(&self.surface)
            .map_err(|e| GpuError::Window {
                detail: format!("make current: {e}"),
            })
    }

    /// Resizes the window to the target, blits the target into it, swaps, and returns the
    /// front buffer (what the window shows), top row first.
    pub fn present(
        &mut self,
        gl: &glow::Context,
        target: &RenderTarget,
    ) -> Result<image::RgbaImage, GpuError> {
        self.make_current()?;
        let shown = self.blit_and_swap(gl, target.framebuffer(), target.width(), target.height());
        unsafe { gl.bind_framebuffer(glow::FRAMEBUFFER, target.framebuffer()) };
        shown
    }

    /// Resizes the window to w×h, blits `source`'s lower-left w×h into the back buffer,
    /// reads it back and swaps; the picture is what the window shows, top row first.
    fn blit_and_swap(
        &mut self,
        gl: &glow::Context,
        source: Option<glow::Framebuffer>,
        w: u32,
        h: u32,
    ) -> Result<image::RgbaImage, GpuError> {
        self.resize(w, h)?;
        self.make_current()?;
        unsafe {
            gl.bind_framebuffer(glow::READ_FRAMEBUFFER, source);
            gl.bind_framebuffer(glow::DRAW_FRAMEBUFFER, None);
            gl.draw_buffer(glow::BACK);
            let (w, h) = (w as i32, h as i32);
            gl.blit_framebuffer(
                0,
                0,
                w,
                h,
                0,
                0,
                w,
                h,
                glow::COLOR_BUFFER_BIT,
                glow::NEAREST,
            );
        }
        // What the window shows is the back buffer once swapped: read it just before the
        // swap (the front buffer of a composited or unmapped X window cannot be read back
        // reliably).
        let mut data = vec![0u8; (w * h * 4) as usize];
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
            gl.read_buffer(glow::BACK);
            gl.pixel_store_i32(glow::PACK_ALIGNMENT, 1);
            gl.read_pixels(
                0,
                0,
                w as i32,
                h as i32,
                glow::RGBA,
                glow::UNSIGNED_BYTE,
                glow::PixelPackData::Slice(Some(&mut data)),
            );
        }
        self.surface
            .swap_buffers(&self.context)
            .map_err(|e| GpuError::Window {
                detail: format!("swap buffers: {e}"),
            })?;
        let row = (w * 4) as usize;
        let flipped: Vec<u8> = data.chunks_exact(row).rev().flatten().copied().collect();
        image::RgbaImage::from_raw(w, h, flipped).ok_or(GpuError::Window {
            detail: "window readback has the wrong length".into(),
        })
    }

    /// Waits until the user does something to the window, a [`Waker`] wakes it, or
    /// `timeout` passes (`None`: no timeout), and returns what the user did.
    pub fn wait_input(&mut self, timeout: Option<Duration>) -> Vec<Input> {
        let collect = &mut self.collect;
        EVENT_LOOP.with(|cell| {
            if let Some(event_loop) = cell.borrow_mut().as_mut() {
                let _ = event_loop.pump_app_events(timeout, collect);
            }
        });
        std::mem::take(&mut self.collect.inputs)
    }

    /// A handle that ends [`wait_input`](Self::wait_input) from another thread.
    pub fn waker(&self) -> Waker {
        Waker {
            proxy: EVENT_LOOP.with(|cell| cell.borrow().as_ref().map(|l| l.create_proxy())),
        }
    }

    /// Shows `picture` (top row first) in the window, sized to it, and returns what the
    /// window shows: the picture is uploaded to a texture, blitted (NEAREST, same size:
    /// exact) into the back buffer, read back and swapped.
    pub fn show(
        &mut self,
        gl: &glow::Context,
        picture: &image::RgbaImage,
    ) -> Result<image::RgbaImage, GpuError> {
        let (w, h) = picture.dimensions();
        self.make_current()?;
        // GL's rows run bottom to top.
        let row = (w * 4) as usize;
        let flipped: Vec<u8> = picture
            .as_raw()
            .chunks_exact(row)
            .rev()
            .flatten()
            .copied()
            .collect();
        // SAFETY: the context is current; the texture and framebuffer live for this call.
        let (texture, framebuffer) = unsafe {
            let texture = gl
                .create_texture()
                .map_err(|detail| GpuError::Window { detail })?;
            gl.bind_texture(glow::TEXTURE_2D, Some(texture));
            gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 1);
            gl.tex_image_2d(
                glow::TEXTURE_2D,
                0,
                glow::RGBA8 as i32,
                w as i32,
                h as i32,
                0,
                glow::RGBA,
                glow::UNSIGNED_BYTE,
                glow::PixelUnpackData::Slice(Some(&flipped)),
            );
            let framebuffer = gl
                .create_framebuffer()
                .map_err(|detail| GpuError::Window { detail })?;
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(framebuffer));
            gl.framebuffer_texture_2d(
                glow::FRAMEBUFFER,
                glow::COLOR_ATTACHMENT0,
                glow::TEXTURE_2D,
                Some(texture),
                0,
            );
            (texture, framebuffer)
        };
        let shown = self.blit_and_swap(gl, Some(framebuffer), w, h);
        // SAFETY: as above.
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
            gl.delete_framebuffer(framebuffer);
            gl.delete_texture(texture);
        }
        shown
    }

    /// Asks the X server for a w×h window and waits (at most two seconds) until it is.
    fn resize(&mut self, w: u32, h: u32) -> Result<(), GpuError> {
        let want = PhysicalSize::new(w, h);
        if self.window.inner_size() != want {
            let _ = self.window.request_inner_size(want);
            let start = Instant::now();
            while self.window.inner_size() != want && start.elapsed() < Duration::from_secs(2) {
                EVENT_LOOP.with(|cell| {
                    if let Some(event_loop) = cell.borrow_mut().as_mut() {
                        pump(event_loop, Duration::from_millis(10));
                    }
                });
            }
            if self.window.inner_size() != want {
                return Err(GpuError::Window {
                    detail: format!(
                        "the window is {:?}, not the {w}x{h} the target needs",
                        self.window.inner_size()
                    ),
                });
            }
        }
        let (nw, nh) = (
            NonZeroU32::new(w).ok_or(GpuError::TargetSize {
                width: w,
                height: h,
                limit: 0,
            })?,
            NonZeroU32::new(h).ok_or(GpuError::TargetSize {
                width: w,
                height: h,
                limit: 0,
            })?,
        );
        self.surface.resize(&self.context, nw, nh);
        Ok(())
    }
}

impl Drop for WindowContext {
    fn drop(&mut self) {
        // Release the thread: glvnd lets one window-system API (GLX or EGL) be current per
        // thread, so a context left current here would block a later EGL context.
        let _ = self.context.make_not_current_in_place();
    }
}
