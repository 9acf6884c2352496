//! Lecture material written without a window: a deck's handout (every
//! slide's figures and an index with titles and notes) and the frames of a
//! played history (numbered PNGs and an animated PNG).

use crate::deck::{LoadedDeck, slide_folder};
use crate::figure::Figure;
use crate::files::{FileSet, write_atomically};
use crate::preset::Preset;
use crate::provenance::{Stamp, figure_bytes};
use crate::scene::{self, Progress, SceneError, SceneOutput, SceneParams};
use anyhow::{Context, Result, bail};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// Writes the handout of `deck` into `dir`: one folder per slide
/// ("01-title") with its figures (PNG, SVG, CSV, each carrying the slide's
/// state) and scalars, and `index.md` listing the slides in order with
/// their titles, notes and figures. `progress` is told of each slide in
/// turn. Returns the files written.
pub fn deck(deck: &LoadedDeck, dir: &Path, progress: &dyn Fn(usize, &str)) -> Result<Vec<PathBuf>> {
    std::fs::create_dir_all(dir).with_context(|| format!("cannot create folder {}", dir.display()))?;
    let mut index = String::new();
    let title = if deck.deck.title.is_empty() { "Lecture" } else { deck.deck.title.as_str() };
    let _ = writeln!(index, "# {title}\n");
    if !deck.deck.description.is_empty() {
        let _ = writeln!(index, "{}\n", deck.deck.description);
    }
    let _ = writeln!(index, "Made with {} from `{}`.\n", crate::provenance::program(), deck.origin);
    let mut written = Vec::new();
    for (i, (slide, params)) in deck.deck.slides.iter().zip(&deck.params).enumerate() {
        progress(i, &slide.title);
        let out = scene::compute(params, &Progress::default())
            .with_context(|| format!("slide {} ('{}')", i + 1, slide.title))?;
        let folder = slide_folder(i, slide);
        let preset = Preset {
            title: slide.title.clone(),
            description: slide.notes.clone(),
            scene: params.clone(),
            sensitivity: None,
        };
        let files = crate::export::write_outputs(&out, Some(&preset), &dir.join(&folder))?;
        written.extend(files);
        let info = params.info();
        let _ = writeln!(index, "## {}. {}\n", i + 1, slide.title);
        let _ = writeln!(index, "*Scene: {} ({})*\n", info.title, info.source);
        for line in slide.notes.lines() {
            let _ = writeln!(index, "{line}");
        }
        index.push('\n');
        let mut figures = params.exported_figures(&out);
        // The enlarged figure first, as on the slide.
        if let Some(big) = &slide.enlarge
            && let Some(k) = figures.iter().position(|f| &f.id == big)
        {
            let f = figures.remove(k);
            figures.insert(0, f);
        }
        for fig in &figures {
            let _ = writeln!(
                index,
                "![{}]({folder}/{}.png)  \n[SVG]({folder}/{}.svg) · [CSV]({folder}/{}.csv)\n",
                fig.title, fig.id, fig.id, fig.id
            );
        }
    }
    let path = dir.join("index.md");
    write_atomically(&path, index.as_bytes())?;
    written.push(path);
    Ok(written)
}

/// Size of movie frames, pixels.
pub const FRAME_SIZE: (u32, u32) = (1200, 825);

/// The figures of `params`' scene at `frames` evenly spaced cursor positions
/// over its history (first to last), with the cursor's marks drawn.
pub fn frames(params: &SceneParams, out: &SceneOutput, frames: usize) -> Result<Vec<Vec<Figure>>, SceneError> {
    let n = frames.max(2);
    let mut probe = params.clone();
    if probe.cursor_mut().is_none() {
        return Err(SceneError::Param(scene::ParamError::Inconsistent(format!(
            "scene '{}' has no time to play (scenes with a time cursor: hysteresis, rocking, growth-tracks, mass-distribution, surface-density, disk-map)",
            params.info().id
        ))));
    }
    (0..n)
        .map(|k| {
            let mut p = params.clone();
            if let Some(c) = p.cursor_mut() {
                *c = k as f64 / (n - 1) as f64;
            }
            let cursor = p
                .cursor(out)
                .ok_or_else(|| SceneError::Param(scene::ParamError::Inconsistent("no history to play".into())))?;
            let mut figures = out.figures.clone();
            cursor.apply(&mut figures);
            Ok(figures)
        })
        .collect()
}

/// Writes a played history into `dir`: for each figure (or only `only`),
/// numbered frames `ID-0001.png` … and, with `animate`, one animated PNG
/// `ID.png` playing them at `fps`. All or nothing. Returns the files written.
pub fn movie(
    preset: &Preset,
    n_frames: usize,
    only: Option<&str>,
    animate: bool,
    fps: u16,
    dir: &Path,
    cancelled: &dyn Fn() -> bool,
) -> Result<Vec<PathBuf>> {
    let files = movie_files(preset, n_frames, only, animate, fps, cancelled)?;
    std::fs::create_dir_all(dir).with_context(|| format!("cannot create folder {}", dir.display()))?;
    let mut set = FileSet::new();
    for (name, bytes) in &files {
        set.stage(&dir.join(name), bytes)?;
    }
    Ok(set.commit()?)
}

/// The files of a played history, as [`movie`] writes them: (file name,
/// bytes), frames first, each figure's animated PNG after its frames.
pub fn movie_files(
    preset: &Preset,
    n_frames: usize,
    only: Option<&str>,
    animate: bool,
    fps: u16,
    cancelled: &dyn Fn() -> bool,
) -> Result<Vec<(String, Vec<u8>)>> {
    let out = scene::compute(&preset.scene, &Progress::default())?;
    let played = frames(&preset.scene, &out, n_frames)?;
    let ids: Vec<String> = out.figures.iter().map(|f| f.id.clone()).filter(|id| only.is_none_or(|o| o == id)).collect();
    if ids.is_empty() {
        let known: Vec<&str> = out.figures.iter().map(|f| f.id.as_str()).collect();
        bail!("no figure '{}' in this scene (figures: {})", only.unwrap_or_default(), known.join(", "));
    }
    let stamp = Stamp::of(preset)?;
    let mut files = Vec::new();
    for id in &ids {
        let mut images = Vec::new();
        for (k, figs) in played.iter().enumerate() {
            if cancelled() {
                bail!("cancelled; nothing was written");
            }
            let Some(fig) = figs.iter().find(|f| &f.id == id) else { continue };
            let bytes = figure_bytes(fig, "png", FRAME_SIZE, Some(&stamp))?;
            if animate {
                images.push(bytes.clone());
            }
            files.push((format!("{id}-{:04}.png", k + 1), bytes));
        }
        if animate {
            let apng = animated_png(&images, fps, &stamp).with_context(|| format!("cannot animate figure '{id}'"))?;
            files.push((format!("{id}.png"), apng));
        }
    }
    Ok(files)
}

/// The size of one figure in a [`movie_sheet`], pixels.
pub const SHEET_CELL: (u32, u32) = (800, 550);

/// A played history as one file: an animated PNG showing every figure of
/// the scene side by side (two to a row), `n_frames` frames at `fps`
/// (what a browser downloads, where a folder of frames would be a download
/// each). Returns the file's name and bytes.
pub fn movie_sheet(
    preset: &Preset,
    n_frames: usize,
    fps: u16,
    cancelled: &dyn Fn() -> bool,
) -> Result<(String, Vec<u8>)> {
    let out = scene::compute(&preset.scene, &Progress::default())?;
    let played = frames(&preset.scene, &out, n_frames)?;
    let ids: Vec<&str> = out.figures.iter().map(|f| f.id.as_str()).collect();
    let stamp = Stamp::of(preset)?;
    let cols = ids.len().clamp(1, 2) as u32;
    let rows = ids.len().div_ceil(2).max(1) as u32;
    let (cw, ch) = SHEET_CELL;
    let (w, h) = (cw * cols, ch * rows);
    let mut sheets = Vec::with_capacity(played.len());
    for figs in &played {
        if cancelled() {
            bail!("cancelled; nothing was written");
        }
        let mut sheet = vec![255u8; (w * h * 3) as usize];
        for (k, id) in ids.iter().enumerate() {
            let Some(fig) = figs.iter().find(|f| f.id == *id) else { continue };
            let (fw, fh, rgb) = decoded_rgb(&figure_bytes(fig, "png", SHEET_CELL, Some(&stamp))?)?;
            let (x0, y0) = ((k as u32 % cols) * cw, (k as u32 / cols) * ch);
            for y in 0..fh.min(ch) {
                let from = (y * fw * 3) as usize;
                let to = (((y0 + y) * w + x0) * 3) as usize;
                let n = (fw.min(cw) * 3) as usize;
                sheet[to..to + n].copy_from_slice(&rgb[from..from + n]);
            }
        }
        sheets.push(sheet);
    }
    let name = format!("{}-movie.png", preset.scene.info().id);
    Ok((name, encode_apng(w, h, &sheets, fps, &stamp)?))
}

/// A PNG's pixels as 8-bit RGB (width, height, bytes).
fn decoded_rgb(bytes: &[u8]) -> Result<(u32, u32, Vec<u8>)> {
    let mut decoder = png::Decoder::new(std::io::Cursor::new(bytes));
    decoder.set_transformations(png::Transformations::EXPAND | png::Transformations::STRIP_16);
    let mut reader = decoder.read_info()?;
    let mut buf = vec![0; reader.output_buffer_size().unwrap_or(0)];
    let info = reader.next_frame(&mut buf)?;
    buf.truncate(info.buffer_size());
    let rgb = match info.color_type {
        png::ColorType::Rgb => buf,
        png::ColorType::Rgba => buf.chunks_exact(4).flat_map(|p| [p[0], p[1], p[2]]).collect(),
        png::ColorType::Grayscale => buf.iter().flat_map(|&g| [g, g, g]).collect(),
        png::ColorType::GrayscaleAlpha => buf.chunks_exact(2).flat_map(|p| [p[0], p[0], p[0]]).collect(),
        png::ColorType::Indexed => bail!("an indexed PNG was not expanded"),
    };
    Ok((info.width, info.height, rgb))
}

/// Joins PNG frames of equal size into one animated PNG (APNG) that loops,
/// each frame shown for 1/`fps` s; viewers without APNG show the first frame.
fn animated_png(frames: &[Vec<u8>], fps: u16, stamp: &Stamp) -> Result<Vec<u8>> {
    let decoded: Vec<(u32, u32, Vec<u8>)> = frames.iter().map(|bytes| decoded_rgb(bytes)).collect::<Result<_>>()?;
    let Some((w, h, _)) = decoded.first() else { bail!("no frames") };
    let (w, h) = (*w, *h);
    if decoded.iter().any(|(fw, fh, _)| (*fw, *fh) != (w, h)) {
        bail!("frames differ in size");
    }
    let raw: Vec<Vec<u8>> = decoded.into_iter().map(|(_, _, data)| data).collect();
    encode_apng(w, h, &raw, fps, stamp)
}

/// Encodes 8-bit RGB frames of `w` × `h` pixels as an animated PNG that
/// loops at `fps`, with the stamp's text chunks.
fn encode_apng(w: u32, h: u32, frames: &[Vec<u8>], fps: u16, stamp: &Stamp) -> Result<Vec<u8>> {
    if frames.is_empty() {
        bail!("no frames");
    }
    let mut out = Vec::new();
    {
        let mut encoder = png::Encoder::new(&mut out, w, h);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_depth(png::BitDepth::Eight);
        for (k, v) in stamp.png_text() {
            encoder.add_itxt_chunk(k.to_string(), v.to_string())?;
        }
        encoder.set_animated(frames.len() as u32, 0)?;
        encoder.set_frame_delay(1, fps.max(1))?;
        let mut writer = encoder.write_header()?;
        for data in frames {
            writer.write_image_data(data)?;
        }
        writer.finish()?;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Frames of a played collision: the cursor's point moves along the
    /// loop, the first frame at the start of contact and the last at its end.
    #[test]
    fn a_played_collision_moves_its_cursor() {
        let preset = crate::preset::resolve("ice-bounce-8ms").expect("shipped");
        let out = scene::compute(&preset.scene, &Progress::default()).expect("computes");
        let played = frames(&preset.scene, &out, 5).expect("frames");
        assert_eq!(played.len(), 5);
        let marker = |figs: &Vec<Figure>| {
            let fig = figs.iter().find(|f| f.id == "contact-radius").expect("figure");
            fig.series.iter().find(|s| s.name == "time cursor").expect("cursor").points[0]
        };
        let (first, mid, last) = (marker(&played[0]), marker(&played[2]), marker(&played[4]));
        assert!(first[0].abs() < 1e-6, "contact starts at δ = 0: {first:?}");
        assert!(mid[1] > 0.0 && mid != last, "{mid:?} {last:?}");
        let budget = played[2].iter().find(|f| f.id == "energy-budget").expect("budget");
        let marks =
            budget.series.len() - out.figures.iter().find(|f| f.id == "energy-budget").map_or(0, |f| f.series.len());
        assert!(marks >= 6, "a time line and five energies: {marks}");
    }

    /// A movie as one file: every figure of the played collision side by
    /// side in one looping animated PNG, its frames differing.
    #[test]
    fn a_movie_sheet_is_one_animated_png_of_every_figure() {
        let preset = crate::preset::resolve("ice-bounce-8ms").expect("shipped");
        let figures = scene::compute(&preset.scene, &Progress::default()).expect("computes").figures.len();
        let (name, bytes) = movie_sheet(&preset, 4, 12, &|| false).expect("sheet");
        assert!(name.ends_with("-movie.png"), "{name}");
        let mut reader = png::Decoder::new(std::io::Cursor::new(bytes.as_slice())).read_info().expect("decodes");
        let info = reader.info();
        let control = info.animation_control().expect("animated");
        assert_eq!(control.num_frames, 4);
        let cols = figures.clamp(1, 2) as u32;
        assert_eq!((info.width, info.height), (SHEET_CELL.0 * cols, SHEET_CELL.1 * figures.div_ceil(2) as u32));
        let mut first = vec![0; reader.output_buffer_size().unwrap_or(0)];
        reader.next_frame(&mut first).expect("frame 1");
        let mut last = first.clone();
        for _ in 1..4 {
            reader.next_frame(&mut last).expect("frame");
        }
        assert_ne!(first, last, "the frames move");
    }

    /// A scene without a history is refused with the scenes that have one.
    #[test]
    fn scenes_without_time_are_refused() {
        let preset = crate::preset::resolve("restitution-ice").expect("shipped");
        let err = frames(&preset.scene, &SceneOutput::default(), 3).expect_err("no time").to_string();
        assert!(err.contains("no time to play") && err.contains("hysteresis"), "{err}");
    }

    /// The animated PNG holds every frame and the preset.
    #[test]
    fn movies_are_written_with_an_animation() {
        let preset = crate::preset::resolve("rolling-psl-aluminium-rocking").expect("shipped");
        let dir = tempfile::tempdir().expect("tempdir");
        let files = movie(&preset, 4, Some("rocking-displacement"), true, 8, dir.path(), &|| false).expect("movie");
        assert_eq!(files.len(), 5);
        let apng = std::fs::read(dir.path().join("rocking-displacement.png")).expect("apng");
        let reader = png::Decoder::new(std::io::Cursor::new(apng)).read_info().expect("decodes");
        assert_eq!(reader.info().animation_control().map(|a| a.num_frames), Some(4));
        assert_eq!(
            crate::preset::read_embedded(&dir.path().join("rocking-displacement-0002.png")).expect("state"),
            preset
        );
    }
}
