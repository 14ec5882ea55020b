//! The viewer's two helper threads and the one channel they report on.
//!
//! - **The window thread** owns the window's GL context (a core 3.3 context of the window
//!   backend) and its event loop: it waits in the X connection for input (no CPU while
//!   idle), forwards what the user did as [`Event::Input`], and shows the pictures the main
//!   thread sends, answering each with what the window then shows. The main thread renders
//!   on its own, headless context: each thread keeps one context current for its life, so
//!   no thread ever switches between GLX and EGL.
//! - **The truth worker** ray-casts the truth of the latest view it was asked for (older
//!   requests still queued are skipped) and reports it as [`Event::Truth`], so a frame
//!   never waits for the truth.
//!
//! Both stop when their handle drops: the window thread is told to quit and woken, the
//! worker's request channel closes; both are joined.

use std::sync::mpsc::{self, Receiver, Sender, TryRecvError};
use std::thread::JoinHandle;

use image::RgbaImage;

use crate::gpu::{Backend, ContextRequest, GpuContext, GpuError, Input, Profile, Waker};
use crate::scene::Scene;
use crate::truth::{self, Truth, TruthError, TruthOptions};

/// What the main thread hears.
pub enum Event {
    Input(Input),
    /// The truth of view `id`.
    Truth {
        id: u64,
        result: Box<Result<Truth, TruthError>>,
    },
}

enum ToWindow {
    Show(RgbaImage, Sender<Result<RgbaImage, GpuError>>),
    Quit,
}

/// The window thread.
pub struct WindowThread {
    to: Sender<ToWindow>,
    waker: Waker,
    handle: Option<JoinHandle<()>>,
    /// How the window's context was made.
    pub describe: String,
}

impl WindowThread {
    /// Opens the window on a new thread; its input goes to `events`.
    pub fn spawn(events: Sender<Event>) -> Result<WindowThread, GpuError> {
        let (to, from_main) = mpsc::channel::<ToWindow>();
        let (ready, is_ready) = mpsc::channel::<Result<(Waker, String), GpuError>>();
        let handle = std::thread::Builder::new()
            .name("fixedfunc-window".into())
            .spawn(move || window_loop(&from_main, &ready, &events))
            .map_err(|e| GpuError::Window {
                detail: format!("cannot start the window thread: {e}"),
            })?;
        let started = is_ready.recv().unwrap_or_else(|_| {
            Err(GpuError::Window {
                detail: "the window thread ended before opening the window".into(),
            })
        });
        match started {
            Ok((waker, describe)) => Ok(WindowThread {
                to,
                waker,
                handle: Some(handle),
                describe,
            }),
            Err(e) => {
                let _ = handle.join();
                Err(e)
            }
        }
    }

    /// Shows `picture` and returns what the window shows.
    pub fn show(&self, picture: RgbaImage) -> Result<RgbaImage, GpuError> {
        let (reply, answer) = mpsc::channel();
        let gone = || GpuError::Window {
            detail: "the window thread has ended".into(),
        };
        self.to
            .send(ToWindow::Show(picture, reply))
            .map_err(|_| gone())?;
        self.waker.wake();
        answer.recv().map_err(|_| gone())?
    }
}

impl Drop for WindowThread {
    fn drop(&mut self) {
        let _ = self.to.send(ToWindow::Quit);
        self.waker.wake();
        if let Some(h) = self.handle.take() {
            let _ = h.join();
        }
    }
}

fn window_loop(
    from_main: &Receiver<ToWindow>,
    ready: &Sender<Result<(Waker, String), GpuError>>,
    events: &Sender<Event>,
) {
    let mut ctx = match GpuContext::new(&ContextRequest::new(Backend::Window, Profile::Core33)) {
        Ok(ctx) => ctx,
        Err(e) => {
            let _ = ready.send(Err(e));
            return;
        }
    };
    if ready
        .send(Ok((ctx.waker(), ctx.path().to_string())))
        .is_err()
    {
        return;
    }
    loop {
        loop {
            match from_main.try_recv() {
                Ok(ToWindow::Show(picture, reply)) => {
                    let _ = reply.send(ctx.show(&picture));
                }
                Ok(ToWindow::Quit) | Err(TryRecvError::Disconnected) => return,
                Err(TryRecvError::Empty) => break,
            }
        }
        for input in ctx.wait_input(None) {
            if events.send(Event::Input(input)).is_err() {
                return;
            }
        }
    }
}

/// The truth worker.
pub struct TruthWorker {
    requests: Option<Sender<(u64, Scene)>>,
    handle: Option<JoinHandle<()>>,
}

impl TruthWorker {
    /// Starts the worker; truths go to `events`.
    pub fn spawn(events: Sender<Event>, options: TruthOptions) -> TruthWorker {
        let (requests, queue) = mpsc::channel::<(u64, Scene)>();
        let handle = std::thread::Builder::new()
            .name("fixedfunc-truth".into())
            .spawn(move || {
                while let Ok(mut latest) = queue.recv() {
                    // Only the newest view matters: skip the ones already overtaken.
                    while let Ok(newer) = queue.try_recv() {
                        latest = newer;
                    }
                    let (id, scene) = latest;
                    let result = Box::new(truth::truth(&scene, &options));
                    if events.send(Event::Truth { id, result }).is_err() {
                        return;
                    }
                }
            })
            .ok();
        TruthWorker {
            requests: Some(requests),
            handle,
        }
    }

    /// Asks for the truth of view `id` of `scene`; false when the worker is gone.
    pub fn request(&self, id: u64, scene: Scene) -> bool {
        self.handle.is_some()
            && self
                .requests
                .as_ref()
                .is_some_and(|r| r.send((id, scene)).is_ok())
    }
}

impl Drop for TruthWorker {
    fn drop(&mut self) {
        self.requests.take();
        if let Some(h) = self.handle.take() {
            let _ = h.join();
        }
    }
}
