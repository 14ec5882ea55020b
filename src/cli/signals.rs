//! What the process does when a signal ends it. SIGINT (Ctrl-C), SIGTERM, SIGHUP and
//! SIGPIPE (a reader such as `head` closed our stdout) end the process as they always
//! would — the exit status is the signal's, `128 + n` in a shell: 130, 143, 129, 141 — but
//! first the handler stops the private X servers the process started
//! (`gpu::stop_private_displays`): a process ended by a signal runs no destructors, and
//! an Xvfb left behind outlives it and keeps its display number. A window's thread that
//! sees its connection to that server break meanwhile waits for the signal rather than
//! letting Xlib exit with status 1 (`gpu::mark_ending`).
//!
//! The handler is async-signal-safe: the server pids are atomics, and it calls only
//! `kill`, `waitpid`, `nanosleep` and `raise`. It is installed with `SA_RESETHAND`, so the
//! signal's default action is back in place when it re-raises the signal; the raised
//! signal is delivered (and ends the process) as the handler returns.

extern "C" fn on_signal(signal: libc::c_int) {
    // A window's thread that sees its X connection break now waits for this signal.
    fixedfunc::gpu::mark_ending();
    fixedfunc::gpu::stop_private_displays();
    // SAFETY: `raise` is async-signal-safe; the disposition is already the default.
    unsafe {
        libc::raise(signal);
    }
}

/// Installs the handler for SIGINT, SIGTERM, SIGHUP and SIGPIPE. Call at start-up, before
/// any thread exists.
pub fn install() {
    for signal in [libc::SIGINT, libc::SIGTERM, libc::SIGHUP, libc::SIGPIPE] {
        // SAFETY: a zeroed `sigaction` is valid (empty mask, no flags); the handler is an
        // `extern "C" fn(c_int)` as `sa_sigaction` without SA_SIGINFO expects.
        unsafe {
            let mut action: libc::sigaction = std::mem::zeroed();
            action.sa_sigaction = on_signal as extern "C" fn(libc::c_int) as libc::sighandler_t;
            action.sa_flags = libc::SA_RESETHAND;
            libc::sigemptyset(&mut action.sa_mask);
            libc::sigaction(signal, &action, std::ptr::null_mut());
        }
    }
}
