//! Figure export: CSV with units in the header, SVG and PNG from the same
//! description, atomic writes.

use grainscope::figure::{Axis, Figure, Series, Style, csv_bytes, png_bytes, svg_string, write_png};

fn figure() -> Figure {
    Figure::new("test", "Test figure", Axis::log("impact velocity v", "m/s"), Axis::linear("restitution", ""))
        .with(Series::new("model", vec![[1.0, 0.1], [10.0, 0.5], [100.0, 0.9]], Style::Line, 0))
        .with(Series::new("reference", vec![[1.0, 0.2], [100.0, 1.0]], Style::Dashed, 1))
        .with(Series::new("point", vec![[3.0, 0.4], [-1.0, 0.5]], Style::Marker, 2))
}

#[test]
fn csv_header_names_quantities_and_units() {
    let text = String::from_utf8(csv_bytes(&figure()).expect("csv")).expect("utf8");
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("series,impact velocity v [m/s],restitution"));
    assert_eq!(text.lines().count(), 1 + 3 + 2 + 2);
    assert!(text.contains("model,1e1,5e-1"));
}

#[test]
fn svg_and_png_render_the_same_description() {
    let fig = figure();
    let svg = svg_string(&fig, (640, 480)).expect("svg");
    assert!(svg.starts_with("<svg") && svg.contains("Test figure") && svg.contains("polyline"));
    let png = png_bytes(&fig, (640, 480)).expect("png");
    let img = image::load_from_memory(&png).expect("decodes").to_rgb8();
    assert_eq!(img.dimensions(), (640, 480));
    // Not blank: the red model line is drawn.
    assert!(img.pixels().any(|p| p.0 == [214, 39, 40]));
}

#[test]
fn failed_export_leaves_earlier_files_intact() {
    let dir = tempfile::tempdir().expect("tempdir");
    let bad = dir.path().join("no-such-dir/figure.png");
    let err = write_png(&figure(), &bad, (320, 240)).expect_err("unwritable");
    assert!(err.to_string().contains("no-such-dir"));
    let good = dir.path().join("figure.png");
    write_png(&figure(), &good, (320, 240)).expect("writes");
    let before = std::fs::read(&good).expect("read");
    // A directory in the way of the rename: the write fails, the old file stays.
    let blocked = dir.path().join("blocked.png");
    std::fs::create_dir(&blocked).expect("dir");
    assert!(write_png(&figure(), &blocked, (320, 240)).is_err());
    assert_eq!(std::fs::read(&good).expect("read"), before);
    let leftovers: Vec<_> = std::fs::read_dir(dir.path())
        .expect("ls")
        .filter_map(|e| e.ok())
        .filter(|e| e.file_name().to_string_lossy().ends_with(".tmp"))
        .collect();
    assert!(leftovers.is_empty());
}
