//! Figure export: CSV with units in the header, SVG and PNG from the same
//! description, atomic writes.

use grainscope::figure::{
    Axis, EXPORT_SIZE, Figure, Fill, Heatmap, NEUTRAL, PALETTE, Scale, Series, Shape, Style, csv_bytes, png_bytes,
    svg_string, write_png,
};

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
    assert!(svg.starts_with("<svg") && svg.contains(">Test figure</text>") && svg.contains("<path d=\"M"));
    // Text stays text, and the log axis is labelled in powers of ten.
    assert!(svg.contains(">impact velocity v [m/s]</text>"));
    assert!(svg.contains(">10²</text>") && svg.contains(">10</text>"));
    // Legend entries show their line style: the reference is dashed.
    assert!(svg.contains(">reference</text>") && svg.contains("stroke-dasharray"));
    let png = png_bytes(&fig, (640, 480)).expect("png");
    let img = image::load_from_memory(&png).expect("decodes").to_rgb8();
    assert_eq!(img.dimensions(), (640, 480));
    // Not blank: the model line is drawn in the first palette colour.
    assert!(img.pixels().any(|p| p.0 == PALETTE[0]));
}

#[test]
fn exports_are_slide_sized_and_scale_their_lines_and_text() {
    assert!(EXPORT_SIZE.0 >= 1600);
    let small = svg_string(&figure(), (800, 550)).expect("svg");
    let large = svg_string(&figure(), (1600, 1100)).expect("svg");
    let title_size = |svg: &str| -> f64 {
        let k = svg.find(">Test figure</text>").expect("title");
        let tag = &svg[svg[..k].rfind("<text").expect("tag")..k];
        let f = tag.split("font-size=\"").nth(1).and_then(|r| r.split('"').next()).expect("size");
        f.parse().expect("number")
    };
    assert!((title_size(&large) / title_size(&small) - 2.0).abs() < 1e-9);
}

#[test]
fn maps_get_a_colour_bar_or_a_legend_of_their_categories() {
    let x = vec![1.0, 2.0, 3.0];
    let values: Vec<f64> = (0..9).map(|k| k as f64).collect();
    let mut fig = Figure::new("map", "Map", Axis::linear("x", "m"), Axis::linear("y", "m"));
    fig.heatmap = Some(Heatmap::new(x.clone(), x.clone(), values.clone(), "log₁₀ Δv", "m/s"));
    let svg = svg_string(&fig, (800, 550)).expect("svg");
    assert!(svg.contains(">log₁₀ Δv [m/s]</text>"), "colour bar title");
    let cats: Vec<f64> = (0..9).map(|k| (k % 3) as f64).collect();
    fig.heatmap = Some(Heatmap::categorical(x.clone(), x, cats, "source", &["Brownian", "turbulence", "settling"]));
    let svg = svg_string(&fig, (800, 550)).expect("svg");
    for c in ["Brownian", "turbulence", "settling"] {
        assert!(svg.contains(&format!(">{c}</text>")), "{c}");
    }
}

#[test]
fn a_family_gets_a_colour_bar_instead_of_legend_rows() {
    let mut fig = Figure::new("spectrum", "Spectrum", Axis::log("m", "g"), Axis::log("f", ""))
        .family("time", "yr", Scale::Log)
        .y_decades(6.0);
    for (k, t) in [100.005, 215.477, 1000.018].into_iter().enumerate() {
        let pts = (1..50).map(|i| [i as f64, (-(i as f64 - 10.0 * (k + 1) as f64).powi(2) / 20.0).exp()]).collect();
        fig.series.push(Series::new(format!("t = {t} yr"), pts, Style::Line, k).at(t));
    }
    let svg = svg_string(&fig, (800, 550)).expect("svg");
    assert!(svg.contains(">time [yr]</text>"));
    assert!(!svg.contains("t = 100.005"), "family members are not listed one by one");
    // The y-axis stops six decades below the peak, not at the smallest value.
    assert!(!svg.contains(">10⁻⁴⁰</text>") && svg.contains(">10⁻⁵</text>"));
}

#[test]
fn an_event_marked_on_several_curves_is_listed_once_by_its_symbol() {
    let open_circle = Style::Symbol(Shape::Circle, Fill::Open);
    let fig = Figure::new("track", "Track", Axis::log("m", "g"), Axis::log("φ", ""))
        .with(Series::new("full", vec![[1.0, 1.0], [10.0, 0.1]], Style::Line, 0))
        .with(Series::new("collisional", vec![[1.0, 1.0], [10.0, 0.01]], Style::Dashed, 1))
        .with(Series::new("a = λ_mfp (full)", vec![[3.0, 0.3]], open_circle, 0).keyed("a = λ_mfp"))
        .with(Series::new("a = λ_mfp (collisional)", vec![[3.0, 0.1]], open_circle, 1).keyed("a = λ_mfp"))
        .with(
            Series::new("gas (full)", vec![[5.0, 0.2]], Style::Symbol(Shape::Circle, Fill::Filled), 0)
                .keyed("first gas compaction"),
        );
    let legend = fig.legend();
    let texts: Vec<&str> = legend.iter().map(|e| e.0.as_str()).collect();
    assert_eq!(texts, ["full", "collisional", "a = λ_mfp", "first gas compaction"]);
    // Shared by curves of two colours: drawn neutral; one curve: its own colour.
    assert_eq!(legend[2].2, NEUTRAL);
    assert_eq!(legend[3].2, PALETTE[0]);
    // Both files list the entry once; the CSV keeps every point under its own name.
    let svg = svg_string(&fig, (800, 550)).expect("svg");
    assert_eq!(svg.matches(">a = λ_mfp</text>").count(), 1);
    assert!(svg.contains("fill=\"none\""), "an open symbol is an outline");
    let csv = String::from_utf8(csv_bytes(&fig).expect("csv")).expect("utf8");
    assert!(csv.contains("a = λ_mfp (full),") && csv.contains("a = λ_mfp (collisional),"));
}

#[test]
fn every_line_style_and_symbol_renders_to_svg_and_png() {
    let mut styles = vec![
        Style::Line,
        Style::Dashed,
        Style::Dotted,
        Style::Arrow,
        Style::Region,
        Style::Points,
        Style::Marker,
        Style::LowerLimit,
        Style::UpperLimit,
    ];
    for shape in [
        Shape::Circle,
        Shape::Square,
        Shape::Diamond,
        Shape::TriangleDown,
        Shape::TriangleUp,
        Shape::Asterisk,
        Shape::Plus,
    ] {
        styles.extend([Style::Symbol(shape, Fill::Open), Style::Symbol(shape, Fill::Filled)]);
    }
    let mut fig = Figure::new("styles", "Styles", Axis::log("x", "m"), Axis::linear("y", ""));
    for (k, style) in styles.iter().enumerate() {
        let y = k as f64;
        fig.series.push(Series::new(format!("{style:?}"), vec![[1.0, y], [3.0, y + 0.5], [10.0, y]], *style, k));
    }
    // resvg refuses malformed SVG (e.g. an attribute given twice), so this
    // checks every style's markup, in the plot and in the legend.
    let png = png_bytes(&fig, EXPORT_SIZE).expect("every style renders");
    assert!(png.starts_with(b"\x89PNG"));
    // An arrow ends in a filled head.
    let svg = svg_string(&fig, EXPORT_SIZE).expect("svg");
    assert!(svg.matches("Z\" fill=").count() >= 2, "arrowheads in the plot and the legend");
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
