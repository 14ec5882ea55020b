//! `fixedfunc info`: which backends work on this machine and what each context offers.

use fixedfunc::gpu::{Backend, ContextInfo, ContextRequest, GpuContext, Profile, VirtualDisplay};
use serde::Serialize;

use super::error::CliError;

#[derive(Serialize)]
struct BackendReport {
    backend: Backend,
    /// A note on how the backend was reached (e.g. a private Xvfb).
    note: Option<String>,
    contexts: Vec<ProfileReport>,
}

#[derive(Serialize)]
struct ProfileReport {
    profile: Profile,
    #[serde(flatten)]
    result: ProfileResult,
}

#[derive(Serialize)]
#[serde(rename_all = "lowercase")]
enum ProfileResult {
    Context(Box<ContextInfo>),
    Error(String),
}

impl BackendReport {
    fn works(&self) -> bool {
        self.contexts
            .iter()
            .any(|c| matches!(c.result, ProfileResult::Context(_)))
    }
}

pub fn run(only: Option<Backend>, json: bool) -> Result<(), CliError> {
    let backends: Vec<Backend> = only.map_or(Backend::ALL.to_vec(), |b| vec![b]);
    let mut reports = Vec::new();
    let mut _display = None;
    for backend in backends {
        let mut note = None;
        if backend == Backend::Window {
            match VirtualDisplay::start_if_needed() {
                Ok(Some(d)) => {
                    note = Some(format!(
                        "no DISPLAY was set: checked on a private Xvfb {}",
                        d.display()
                    ));
                    _display = Some(d);
                }
                Ok(None) => {}
                Err(e) => note = Some(e.to_string()),
            }
        }
        let contexts = Profile::ALL
            .into_iter()
            .map(|profile| ProfileReport {
                profile,
                result: match GpuContext::new(&ContextRequest::new(backend, profile))
                    .and_then(|ctx| ContextInfo::query(&ctx))
                {
                    Ok(info) => ProfileResult::Context(Box::new(info)),
                    Err(e) => ProfileResult::Error(e.to_string()),
                },
            })
            .collect();
        reports.push(BackendReport {
            backend,
            note,
            contexts,
        });
    }
    if json {
        outln!("{}", serde_json::to_string_pretty(&reports)?)?;
    } else {
        for report in &reports {
            print_text(report)?;
        }
    }
    match (only, reports.first()) {
        (Some(backend), Some(report)) if !report.works() => Err(CliError::BackendUnavailable {
            backend,
            reasons: report
                .contexts
                .iter()
                .filter_map(|c| match &c.result {
                    ProfileResult::Error(e) => Some(e),
                    ProfileResult::Context(_) => None,
                })
                .map(|e| format!("  {e}"))
                .collect::<Vec<_>>()
                .join("\n"),
        }),
        _ => Ok(()),
    }
}

fn print_text(report: &BackendReport) -> Result<(), CliError> {
    let status = if report.works() {
        "works"
    } else {
        "UNAVAILABLE"
    };
    outln!("{}: {status}", report.backend)?;
    if let Some(note) = &report.note {
        outln!("  note: {note}")?;
    }
    for c in &report.contexts {
        match &c.result {
            ProfileResult::Error(e) => outln!(
                "  {:<14} error: {}",
                c.profile.name(),
                e.replace('\n', "\n    ")
            )?,
            ProfileResult::Context(i) => print_context(i)?,
        }
    }
    outln!()
}

fn print_context(i: &ContextInfo) -> Result<(), CliError> {
    outln!("  {:<14} via {}", i.profile.name(), i.path)?;
    outln!("    vendor       {}", i.vendor)?;
    outln!("    renderer     {}", i.renderer)?;
    outln!("    version      {}", i.version)?;
    outln!("    GLSL         {}", i.glsl_version)?;
    let l = &i.limits;
    outln!(
        "    limits       texture {}, renderbuffer {}, viewport {}x{}, image units {}, fixed-function units {}",
        l.max_texture_size,
        l.max_renderbuffer_size,
        l.max_viewport[0],
        l.max_viewport[1],
        l.max_texture_image_units,
        l.max_fixed_function_units
            .map_or("none (core profile)".to_string(), |n| n.to_string()),
    )?;
    let depth: Vec<String> = i
        .depth
        .iter()
        .map(|d| {
            let asked = format!(
                "{:?}{}",
                d.requested,
                if d.stencil_requested { "+S" } else { "" }
            );
            match (d.depth_bits, d.stencil_bits) {
                (Some(z), Some(s)) => format!("{asked} → {z}/{s}"),
                _ => format!("{asked} → unsupported"),
            }
        })
        .collect();
    outln!("    depth/stencil bits obtained: {}", depth.join(", "))?;
    if i.profile == Profile::Core33 {
        outln!("    extensions   none needed: the emulated pipeline builds on GLSL 3.30 alone")?;
        return Ok(());
    }
    let present: Vec<&str> = i
        .extensions
        .iter()
        .filter(|e| e.present)
        .map(|e| e.name)
        .collect();
    let absent: Vec<&str> = i
        .extensions
        .iter()
        .filter(|e| !e.present)
        .map(|e| e.name)
        .collect();
    outln!("    shadow extensions present: {}", present.join(" "))?;
    outln!(
        "    shadow extensions absent:  {}",
        if absent.is_empty() {
            "none".to_string()
        } else {
            absent.join(" ")
        }
    )
}
