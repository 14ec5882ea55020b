//! `fixedfunc info` reports what the headless backends really offer, as text and as JSON.

use std::process::Command;

fn info(args: &[&str]) -> (bool, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_fixedfunc"))
        .arg("info")
        .args(args)
        .output()
        .expect("run fixedfunc info");
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
    )
}

#[test]
fn info_json_reports_both_profiles_and_the_depth_bits_obtained() {
    for backend in ["egl", "osmesa"] {
        let (ok, stdout) = info(&["--backend", backend, "--json"]);
        assert!(ok, "{backend}: {stdout}");
        let reports: serde_json::Value = serde_json::from_str(&stdout).expect("valid JSON");
        let contexts = reports[0]["contexts"].as_array().expect("contexts");
        assert_eq!(contexts.len(), 2);
        for c in contexts {
            let ctx = &c["context"];
            assert!(
                ctx["renderer"].as_str().is_some_and(|r| !r.is_empty()),
                "{c}"
            );
            // D24 always comes with 8 stencil bits; D32F with stencil asked for too.
            let depth = ctx["depth"].as_array().expect("depth reports");
            let d24 = depth
                .iter()
                .find(|d| d["requested"] == "D24" && d["stencil_requested"] == false)
                .expect("D24 row");
            assert_eq!(
                (d24["depth_bits"].as_u64(), d24["stencil_bits"].as_u64()),
                (Some(24), Some(8))
            );
        }
        // The compatibility profile lists the fixed-function extensions the techniques use.
        let compat = &contexts[1]["context"];
        assert_eq!(compat["profile"], "compatibility");
        let ext = compat["extensions"].as_array().expect("extensions");
        let present = |name: &str| {
            ext.iter()
                .any(|e| e["name"] == name && e["present"] == true)
        };
        assert!(present("GL_ARB_texture_env_combine") && present("GL_ARB_shadow"));
        assert!(
            !present("GL_NV_register_combiners"),
            "Mesa has no register combiners"
        );
    }
}

#[test]
fn info_text_names_the_path_each_backend_took() {
    let (ok, stdout) = info(&["--backend", "egl"]);
    assert!(ok);
    assert!(stdout.starts_with("egl: works"), "{stdout}");
    assert!(
        stdout.contains("via EGL_MESA_platform_surfaceless"),
        "{stdout}"
    );
    assert!(stdout.contains("fixed-function units 8"), "{stdout}");
}
