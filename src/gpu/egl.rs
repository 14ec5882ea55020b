//! EGL without a window system. The surfaceless platform (`EGL_MESA_platform_surfaceless`,
//! 0x31DD) is tried first; if the client extensions lack it, the device platform
//! (`EGL_EXT_platform_device`, 0x313F) on the first device `eglQueryDevicesEXT` lists. The
//! context is made current with no surface (`EGL_KHR_surfaceless_context`), so rendering
//! goes to framebuffer objects — or, once [`EglContext::bind_pbuffer`] gave it one, with a
//! pbuffer surface, whose framebuffer 0 is a window-system framebuffer as OSMesa's buffer
//! is: Mesa rasterises it upside down in memory (`Y_0_TOP`), and the tie rules of lines
//! follow that orientation. The context has no config (`EGL_KHR_no_config_context`) when
//! the display allows, so a pbuffer of any config can be bound to it.

use std::cell::Cell;
use std::ffi::c_void;

use khronos_egl as egl;

use super::{Backend, GpuError, Profile};

const PLATFORM_SURFACELESS_MESA: egl::Enum = 0x31DD;
const PLATFORM_DEVICE_EXT: egl::Enum = 0x313F;
const DEFAULT_LIBRARY: &str = "libEGL.so.1";

type Egl = egl::DynamicInstance<egl::EGL1_5>;
type QueryDevices = unsafe extern "system" fn(i32, *mut *mut c_void, *mut i32) -> egl::Boolean;

/// Which EGL platform gave the display (or, in a request, which one to use; `None` in a
/// request means "surfaceless, else device").
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum EglPlatform {
    Surfaceless,
    Device,
}

impl std::fmt::Display for EglPlatform {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            EglPlatform::Surfaceless => "EGL_MESA_platform_surfaceless",
            EglPlatform::Device => "EGL_EXT_platform_device",
        })
    }
}

pub struct EglContext {
    egl: Egl,
    display: egl::Display,
    context: egl::Context,
    platform: EglPlatform,
    /// Made without a config: any pbuffer can be bound.
    configless: bool,
    /// The pbuffer made current with the context, if any (`bind_pbuffer`).
    pbuffer: Cell<Option<egl::Surface>>,
}

/// The buffers of a pbuffer surface: 8-bit red, green and blue, and these.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PbufferSpec {
    pub width: u32,
    pub height: u32,
    pub alpha_bits: i32,
    pub depth_bits: i32,
    pub stencil_bits: i32,
}

/// EGL_NO_CONFIG_KHR (EGL_KHR_no_config_context).
const NO_CONFIG: *mut c_void = std::ptr::null_mut();

fn egl_err(call: &'static str, platform: EglPlatform) -> impl Fn(egl::Error) -> GpuError {
    move |e| GpuError::Egl {
        call,
        platform: match platform {
            EglPlatform::Surfaceless => "surfaceless",
            EglPlatform::Device => "device",
        },
        code: format!("{e} ({e:?})"),
    }
}

impl EglContext {
    pub fn create(
        profile: Profile,
        library: Option<&str>,
        platform: Option<EglPlatform>,
    ) -> Result<(EglContext, glow::Context), GpuError> {
        let library = library.unwrap_or(DEFAULT_LIBRARY);
        // SAFETY: the library is Mesa's (or glvnd's) libEGL, which implements EGL 1.5.
        let egl = unsafe { Egl::load_required_from_filename(library) }.map_err(|e| {
            GpuError::LibraryMissing {
                backend: Backend::Egl,
                library: library.to_string(),
                reason: e.to_string(),
                debian_packages: "libegl1 libegl-mesa0 libgl1-mesa-dri",
                hint: "",
            }
        })?;
        let (display, platform) = open_display(&egl, platform)?;
        let err = |call| egl_err(call, platform);
        egl.initialize(display).map_err(err("eglInitialize"))?;
        egl.bind_api(egl::OPENGL_API).map_err(err("eglBindAPI"))?;
        let config = egl
            .choose_first_config(
                display,
                &[
                    egl::RENDERABLE_TYPE,
                    egl::OPENGL_BIT,
                    egl::SURFACE_TYPE,
                    egl::DONT_CARE,
                    egl::NONE,
                ],
            )
            .map_err(err("eglChooseConfig"))?
            .ok_or(GpuError::Egl {
                call: "eglChooseConfig",
                platform: "headless",
                code: "no config renders OpenGL".into(),
            })?;
        let attribs: &[egl::Int] = match profile {
            Profile::Core33 => &[
                egl::CONTEXT_MAJOR_VERSION,
                3,
                egl::CONTEXT_MINOR_VERSION,
                3,
                egl::CONTEXT_OPENGL_PROFILE_MASK,
                egl::CONTEXT_OPENGL_CORE_PROFILE_BIT,
                egl::NONE,
            ],
            // No version: the driver's highest compatibility profile (4.5 on llvmpipe).
            Profile::Compatibility => &[
                egl::CONTEXT_OPENGL_PROFILE_MASK,
                egl::CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT,
                egl::NONE,
            ],
        };
        let configless = egl
            .query_string(Some(display), egl::EXTENSIONS)
            .map(|s| {
                s.to_string_lossy()
                    .split_whitespace()
                    .any(|e| e == "EGL_KHR_no_config_context")
            })
            .unwrap_or(false);
        // SAFETY: EGL_NO_CONFIG_KHR is a valid config argument where the display lists
        // EGL_KHR_no_config_context.
        let no_config = unsafe { egl::Config::from_ptr(NO_CONFIG) };
        let context = egl
            .create_context(
                display,
                if configless { no_config } else { config },
                None,
                attribs,
            )
            .map_err(err("eglCreateContext"))?;
        let ctx = EglContext {
            egl,
            display,
            context,
            platform,
            configless,
            pbuffer: Cell::new(None),
        };
        ctx.make_current()?;
        // SAFETY: the context is current; eglGetProcAddress returns entry points for it.
        let gl = unsafe { glow::Context::from_loader_function(|name| ctx.proc_address(name)) };
        Ok((ctx, gl))
    }

    pub fn proc_address(&self, name: &str) -> *const c_void {
        self.egl
            .get_proc_address(name)
            .map_or(std::ptr::null(), |f| f as *const c_void)
    }

    pub fn platform(&self) -> EglPlatform {
        self.platform
    }

    pub fn make_current(&self) -> Result<(), GpuError> {
        let surface = self.pbuffer.get();
        self.egl
            .make_current(self.display, surface, surface, Some(self.context))
            .map_err(egl_err("eglMakeCurrent", self.platform))
    }

    /// Makes the context current with a new pbuffer of `spec` (the previous one destroyed):
    /// framebuffer 0 is then that surface. Ok(false), and the context as it was, when no
    /// config has exactly these buffers (single-sampled) or the context has a config.
    pub fn bind_pbuffer(&self, spec: PbufferSpec) -> Result<bool, GpuError> {
        let Some(config) = self.exact_config(spec) else {
            return Ok(false);
        };
        let (Ok(w), Ok(h)) = (
            egl::Int::try_from(spec.width),
            egl::Int::try_from(spec.height),
        ) else {
            return Ok(false);
        };
        let attribs = [egl::WIDTH, w, egl::HEIGHT, h, egl::NONE];
        let Ok(surface) = self
            .egl
            .create_pbuffer_surface(self.display, config, &attribs)
        else {
            return Ok(false);
        };
        let old = self.pbuffer.replace(Some(surface));
        if let Err(e) = self.make_current() {
            self.pbuffer.set(old);
            let _ = self.egl.destroy_surface(self.display, surface);
            return Err(e);
        }
        if let Some(old) = old {
            let _ = self.egl.destroy_surface(self.display, old);
        }
        Ok(true)
    }

    /// Makes the context current without a surface again, destroying its pbuffer.
    pub fn release_pbuffer(&self) -> Result<(), GpuError> {
        let Some(old) = self.pbuffer.take() else {
            return Ok(());
        };
        self.make_current()?;
        let _ = self.egl.destroy_surface(self.display, old);
        Ok(())
    }

    /// The single-sampled pbuffer config whose sizes are exactly `spec`'s.
    fn exact_config(&self, spec: PbufferSpec) -> Option<egl::Config> {
        if !self.configless {
            return None;
        }
        // eglChooseConfig takes these as minimums; a config must match each exactly.
        let sizes = [
            (egl::RED_SIZE, 8),
            (egl::GREEN_SIZE, 8),
            (egl::BLUE_SIZE, 8),
            (egl::ALPHA_SIZE, spec.alpha_bits),
            (egl::DEPTH_SIZE, spec.depth_bits),
            (egl::STENCIL_SIZE, spec.stencil_bits),
            (egl::SAMPLES, 0),
        ];
        let mut wanted = vec![
            egl::SURFACE_TYPE,
            egl::PBUFFER_BIT,
            egl::RENDERABLE_TYPE,
            egl::OPENGL_BIT,
        ];
        wanted.extend(sizes.iter().flat_map(|&(a, v)| [a, v]));
        wanted.push(egl::NONE);
        let mut configs = Vec::with_capacity(64);
        self.egl
            .choose_config(self.display, &wanted, &mut configs)
            .ok()?;
        let get = |c: egl::Config, a| self.egl.get_config_attrib(self.display, c, a).ok();
        configs
            .into_iter()
            .find(|&c| sizes.iter().all(|&(a, v)| get(c, a) == Some(v)))
    }
}

impl Drop for EglContext {
    fn drop(&mut self) {
        // Errors here cannot be acted on; the display stays initialised for other contexts
        // of this process (eglTerminate would destroy them too).
        let _ = self.egl.make_current(self.display, None, None, None);
        if let Some(surface) = self.pbuffer.take() {
            let _ = self.egl.destroy_surface(self.display, surface);
        }
        let _ = self.egl.destroy_context(self.display, self.context);
    }
}

/// Opens the surfaceless display, or the first EGL device's display.
fn open_display(
    egl: &Egl,
    wanted: Option<EglPlatform>,
) -> Result<(egl::Display, EglPlatform), GpuError> {
    let extensions = egl
        .query_string(None, egl::EXTENSIONS)
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let has = |name: &str| extensions.split_whitespace().any(|e| e == name);
    if wanted != Some(EglPlatform::Device) && has("EGL_MESA_platform_surfaceless") {
        // SAFETY: the surfaceless platform takes EGL_DEFAULT_DISPLAY as its native display.
        let display = unsafe {
            egl.get_platform_display(
                PLATFORM_SURFACELESS_MESA,
                egl::DEFAULT_DISPLAY,
                &[egl::ATTRIB_NONE],
            )
        }
        .map_err(egl_err("eglGetPlatformDisplay", EglPlatform::Surfaceless))?;
        return Ok((display, EglPlatform::Surfaceless));
    }
    if wanted != Some(EglPlatform::Surfaceless) && has("EGL_EXT_platform_device") {
        let query = egl.get_proc_address("eglQueryDevicesEXT").ok_or_else(|| {
            GpuError::NoHeadlessPlatform {
                extensions: extensions.clone(),
            }
        })?;
        // SAFETY: eglQueryDevicesEXT has this signature (EGL_EXT_device_enumeration).
        let query: QueryDevices = unsafe { std::mem::transmute(query) };
        let mut device: *mut c_void = std::ptr::null_mut();
        let mut count = 0;
        // SAFETY: room for one device handle.
        let ok = unsafe { query(1, &mut device, &mut count) };
        if ok == egl::TRUE && count > 0 {
            // SAFETY: an EGLDeviceEXT is the native display of the device platform.
            let display = unsafe {
                egl.get_platform_display(PLATFORM_DEVICE_EXT, device, &[egl::ATTRIB_NONE])
            }
            .map_err(egl_err("eglGetPlatformDisplay", EglPlatform::Device))?;
            return Ok((display, EglPlatform::Device));
        }
    }
    Err(GpuError::NoHeadlessPlatform { extensions })
}
