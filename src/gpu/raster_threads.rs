//! Where llvmpipe's rasterizer threads run: one per CPU the process may use.
//!
//! llvmpipe makes its rasterizer threads (`llvmpipe-0`, `llvmpipe-1`, …) when a context is
//! created. A frame bins on the calling thread, then wakes every rasterizer thread and
//! sleeps until they have drawn the bins. Linux wakes a sleeping thread on the CPU it last
//! ran on when that CPU is idle, and an idle CPU pulls a queued thread from a busy one only
//! at its periodic balance. On a machine of two CPUs this has a stable bad state: both
//! rasterizer threads last ran on one CPU, both are woken there, the first takes every bin
//! while the second waits in that CPU's queue and the other CPU idles. Measured with
//! `perf sched timehist` on `benches/c/abi_bench.c lists` (2 CPUs, Mesa 22.3.6): in that
//! state one thread ran 1.4–1.5 ms a frame with the other queued as long, and frames took
//! 2.4–3.2 ms for the first few hundred; with the threads on different CPUs each ran
//! ~0.8 ms and frames took ~2.0 ms from the start.
//!
//! So a context's rasterizer threads are each bound to one CPU: thread k to the k-th CPU
//! (modulo their number) of the set the creating thread may run on, which respects
//! `taskset` and cgroup limits. With fewer than two CPUs nothing is bound. The threads are
//! found by name among the threads that did not exist before the context was made, so a
//! program's own threads and other contexts' rasterizers are never touched. llvmpipe names
//! a thread when the thread starts, which may be after context creation returns; the
//! binding is done at the first frame's end, when every rasterizer has run.
//!
//! `FIXEDFUNC_RASTER_THREADS=kernel` leaves placement to the kernel. Binding is a
//! scheduling hint: a kernel that refuses it (`sched_setaffinity` failing) leaves the
//! threads where they were, and the image is the same either way.

use std::collections::HashSet;

/// The environment variable that chooses the placement.
pub const VARIABLE: &str = "FIXEDFUNC_RASTER_THREADS";

/// How a context's rasterizer threads are placed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RasterPlacement {
    /// Thread k bound to the k-th CPU the process may use (the default).
    OnePerCpu,
    /// Left to the kernel's scheduler (`FIXEDFUNC_RASTER_THREADS=kernel`).
    Kernel,
}

impl RasterPlacement {
    /// The placement `FIXEDFUNC_RASTER_THREADS` asks for: `kernel`, or `spread` (the
    /// default, also when unset). Another value is reported on stderr and read as the
    /// default.
    pub fn from_env() -> Self {
        match std::env::var(VARIABLE).as_deref() {
            Ok("kernel") => RasterPlacement::Kernel,
            Ok("spread") | Err(_) => RasterPlacement::OnePerCpu,
            Ok(other) => {
                eprintln!(
                    "fixedfunc: {VARIABLE}={other:?} is not a placement (spread, kernel); \
                     using spread"
                );
                RasterPlacement::OnePerCpu
            }
        }
    }
}

/// The process's threads at one moment, taken before a context is made.
#[derive(Clone, Debug, Default)]
pub struct ThreadsBefore(HashSet<i32>);

impl ThreadsBefore {
    /// The thread ids now in `/proc/self/task`.
    pub fn now() -> Self {
        ThreadsBefore(thread_ids().into_iter().collect())
    }

    /// Binds each rasterizer thread made since `self` was taken (named `llvmpipe-k`) to
    /// one CPU: the k-th, modulo their number, of those the calling thread may run on.
    /// Returns how many threads were bound (0 with fewer than two CPUs).
    pub fn bind_new_rasterizers(&self) -> usize {
        let cpus = allowed_cpus();
        if cpus.len() < 2 {
            return 0;
        }
        let mut bound = 0;
        for tid in thread_ids().into_iter().filter(|t| !self.0.contains(t)) {
            let Some(k) = rasterizer_index(tid) else {
                continue;
            };
            if bind(tid, cpus[k % cpus.len()]) {
                bound += 1;
            }
        }
        bound
    }
}

/// The ids of the process's threads (empty where `/proc` cannot be read).
fn thread_ids() -> Vec<i32> {
    let Ok(dir) = std::fs::read_dir("/proc/self/task") else {
        return Vec::new();
    };
    dir.flatten()
        .filter_map(|e| e.file_name().to_str()?.parse().ok())
        .collect()
}

/// k for a thread named `llvmpipe-k` (llvmpipe's rasterizer k), else None.
fn rasterizer_index(tid: i32) -> Option<usize> {
    let comm = std::fs::read_to_string(format!("/proc/self/task/{tid}/comm")).ok()?;
    comm.trim_end().strip_prefix("llvmpipe-")?.parse().ok()
}

/// The CPUs the calling thread may run on, in order.
fn allowed_cpus() -> Vec<usize> {
    // SAFETY: cpu_set_t is plain bits; sched_getaffinity writes at most its size.
    unsafe {
        let mut set: libc::cpu_set_t = std::mem::zeroed();
        if libc::sched_getaffinity(0, std::mem::size_of::<libc::cpu_set_t>(), &mut set) != 0 {
            return Vec::new();
        }
        (0..libc::CPU_SETSIZE as usize)
            .filter(|&c| libc::CPU_ISSET(c, &set))
            .collect()
    }
}

/// Binds thread `tid` to `cpu`; false when the kernel refuses.
fn bind(tid: i32, cpu: usize) -> bool {
    // SAFETY: cpu_set_t is plain bits; CPU_SET stays within it for cpu < CPU_SETSIZE,
    // which `allowed_cpus` guarantees.
    unsafe {
        let mut set: libc::cpu_set_t = std::mem::zeroed();
        libc::CPU_SET(cpu, &mut set);
        libc::sched_setaffinity(tid, std::mem::size_of::<libc::cpu_set_t>(), &set) == 0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A thread started after the snapshot, named `name`, parked until the test ends;
    /// answers with the CPUs it may run on when asked.
    fn parked(
        name: &str,
    ) -> (
        std::sync::mpsc::Sender<()>,
        std::thread::JoinHandle<Vec<usize>>,
    ) {
        let (tx, rx) = std::sync::mpsc::channel::<()>();
        let handle = std::thread::Builder::new()
            .name(name.into())
            .spawn(move || {
                let _ = rx.recv();
                allowed_cpus()
            })
            .expect("spawn");
        (tx, handle)
    }

    #[test]
    fn new_threads_named_as_rasterizers_are_bound_one_cpu_each_and_others_are_left_alone() {
        let cpus = allowed_cpus();
        let before = ThreadsBefore::now();
        let (go0, other) = parked("not-a-raster");
        let (go1, raster1) = parked("llvmpipe-1");
        // Linux sets a thread's comm when it starts: wait until the rasterizer's shows.
        let deadline = std::time::Instant::now() + std::time::Duration::from_secs(5);
        while !thread_ids()
            .into_iter()
            .any(|t| rasterizer_index(t) == Some(1))
        {
            assert!(
                std::time::Instant::now() < deadline,
                "thread name never appeared"
            );
            std::thread::yield_now();
        }
        let bound = before.bind_new_rasterizers();
        drop((go0, go1));
        let (other, raster1) = (other.join().expect("join"), raster1.join().expect("join"));
        assert_eq!(other, cpus, "a thread of another name keeps its CPUs");
        match cpus.len() {
            0 | 1 => {
                assert_eq!(bound, 0);
                assert_eq!(raster1, cpus);
            }
            n => {
                // Another test's context may have made rasterizers meanwhile: at least ours.
                assert!(bound >= 1);
                assert_eq!(raster1, vec![cpus[1 % n]], "llvmpipe-1 on the second CPU");
            }
        }
    }

    #[test]
    fn the_allowed_cpus_include_the_one_running_now() {
        // SAFETY: sched_getcpu takes no arguments.
        let now = unsafe { libc::sched_getcpu() };
        assert!(now >= 0);
        assert!(allowed_cpus().contains(&(now as usize)));
    }
}
