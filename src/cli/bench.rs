//! `fixedfunc bench`: repeated timings with medians, a progress bar while they run.

use fixedfunc::bench::{context, BenchGroup};
use fixedfunc::gpu::{Backend, Profile, VirtualDisplay};
use indicatif::{ProgressBar, ProgressStyle};

use super::error::CliError;

pub fn run(only: Option<BenchGroup>, repeats: usize, json: bool) -> Result<(), CliError> {
    let groups: Vec<BenchGroup> = only.map_or(BenchGroup::ALL.to_vec(), |g| vec![g]);
    for group in groups {
        match group {
            BenchGroup::Context => run_context(repeats, json)?,
        }
    }
    Ok(())
}

fn run_context(repeats: usize, json: bool) -> Result<(), CliError> {
    let display = VirtualDisplay::start_if_needed();
    let mut backends = vec![Backend::Egl, Backend::OsMesa];
    match &display {
        Ok(_) => backends.push(Backend::Window),
        Err(e) => eprintln!("window backend skipped: {e}"),
    }
    let total = (backends.len() * Profile::ALL.len() * repeats.max(1)) as u64;
    let bar = ProgressBar::new(total).with_style(
        ProgressStyle::with_template("{msg:>22} [{bar:30}] {pos}/{len}")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    let mut rows = Vec::new();
    for &backend in &backends {
        for profile in Profile::ALL {
            bar.set_message(format!("{backend} {}", profile.name()));
            match context::measure(backend, profile, repeats, || bar.inc(1)) {
                Ok(row) => rows.push(row),
                Err(e) => bar.println(format!("{backend} {}: {e}", profile.name())),
            }
        }
    }
    bar.finish_and_clear();
    if json {
        println!("{}", serde_json::to_string_pretty(&rows)?);
        return Ok(());
    }
    println!(
        "context: {} repeats each; milliseconds, median [min–max]",
        repeats.max(1)
    );
    println!(
        "{:<8} {:<14} {:>26} {:>26}",
        "backend", "profile", "create", "first read-back frame"
    );
    for r in &rows {
        let fmt =
            |s: &fixedfunc::bench::Summary| format!("{:.2} [{:.2}–{:.2}]", s.median, s.min, s.max);
        println!(
            "{:<8} {:<14} {:>26} {:>26}",
            r.backend.name(),
            r.profile.name(),
            fmt(&r.create_ms),
            fmt(&r.first_frame_ms)
        );
    }
    Ok(())
}
