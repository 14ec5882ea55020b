use super::*;

/// A mask from rows of characters: '#' shadowed, '.' lit, ' ' background.
fn mask(rows: &[&str]) -> Mask {
    let width = rows[0].len() as u32;
    let data = rows
        .iter()
        .flat_map(|r| {
            r.bytes().map(|c| match c {
                b'#' => SHADOWED,
                b'.' => LIT,
                _ => BACKGROUND,
            })
        })
        .collect();
    Mask {
        width,
        height: rows.len() as u32,
        data,
    }
}

#[test]
fn classes() {
    for (v, c) in [
        (0, Class::Shadowed),
        (127, Class::Shadowed),
        (128, Class::Background),
        (129, Class::Lit),
        (255, Class::Lit),
    ] {
        assert_eq!(Class::of(v), c, "{v}");
    }
}

#[test]
fn counts_table() {
    let truth = mask(&["....", "..##", "..##", "    "]);
    // (name, technique, false, missed, coverage, geometry pixels)
    let cases: [(&str, Mask, u64, u64, u64); 4] = [
        ("identical", truth.clone(), 0, 0, 0),
        (
            "one false",
            mask(&["#...", "..##", "..##", "    "]),
            1,
            0,
            0,
        ),
        (
            "two missed",
            mask(&["....", "...#", "..#.", "    "]),
            0,
            2,
            0,
        ),
        ("coverage", mask(&["... ", "..##", "..##", "...."]), 0, 0, 1),
    ];
    for (name, technique, f, m, c) in cases {
        let got = compare(&technique, &truth, 0).expect("same size");
        assert_eq!(
            (
                got.all.false_shadow,
                got.all.missed_shadow,
                got.all.coverage
            ),
            (f, m, c),
            "{name}"
        );
        assert_eq!(got.all.pixels, 12, "{name}");
        assert_eq!(got.all.wrong, f + m + c, "{name}");
        assert!(
            (got.all.wrong_percent - 100.0 * (f + m + c) as f64 / 12.0).abs() < 1e-12,
            "{name}"
        );
    }
    let extra = compare(&mask(&["....", "..##", "..##", "...."]), &truth, 0).expect("same size");
    assert_eq!(extra.extra_coverage, 4);
}

#[test]
fn band_excludes_edge_errors() {
    let truth = mask(&["......", "...###", "...###", "...###", "......"]);
    // The technique's edge is one column to the left: errors only next to the edge.
    let shifted = mask(&["......", "..####", "..####", "..####", "......"]);
    let m = compare(&shifted, &truth, 1).expect("same size");
    assert_eq!(m.all.false_shadow, 3);
    assert_eq!(
        m.outside_band.false_shadow, 0,
        "a one-pixel shift is inside a 1-band"
    );
    // Both sides of an edge are edge pixels; a two-column shift leaves column 1 outside a
    // 0-band but inside a 1-band.
    let two = mask(&["......", ".#####", ".#####", ".#####", "......"]);
    assert_eq!(
        compare(&two, &truth, 0)
            .expect("same size")
            .outside_band
            .false_shadow,
        3
    );
    assert_eq!(
        compare(&two, &truth, 1)
            .expect("same size")
            .outside_band
            .false_shadow,
        0
    );
}

#[test]
fn edge_band_widths() {
    let truth = mask(&[".....", ".....", "..#..", ".....", "....."]);
    let count = |k| edge_band(&truth, k).iter().filter(|b| **b).count();
    assert_eq!(count(0), 5, "the centre and its 4 neighbours");
    assert_eq!(count(1), 21, "5×5 less the corners");
    assert_eq!(count(2), 25);
    let silhouette = mask(&["  ", ".."]);
    assert_eq!(
        edge_band(&silhouette, 3).iter().filter(|b| **b).count(),
        0,
        "no shadow edge"
    );
}

#[test]
fn errors_and_rmse() {
    let a = Mask::filled(2, 2, LIT);
    assert!(matches!(
        compare(&a, &Mask::filled(3, 2, LIT), 1),
        Err(MetricsError::SizeMismatch { .. })
    ));
    let truth = mask(&[". ", "#."]);
    let rmse =
        visibility_rmse(&[1.0, 0.0, 0.5, 1.0], &[1.0, 0.7, 0.0, 1.0], &truth).expect("sizes");
    assert!((rmse - (0.25f64 / 3.0).sqrt()).abs() < 1e-6, "{rmse}");
    assert!(visibility_rmse(&[1.0], &[1.0; 4], &truth).is_err());
}
