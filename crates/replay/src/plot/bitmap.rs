//! The charts' font and their PNG form: the bundled DejaVu Sans subset (`fonts/`, Bitstream
//! Vera licence) registered with plotters as `sans-serif`, and an RGB buffer drawn by
//! plotters' bitmap backend encoded with the `png` crate.

use std::path::Path;
use std::sync::OnceLock;

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::FontStyle;

use crate::error::{Error, ErrorKind, Result};

/// DejaVu Sans, Latin-1 and a few symbols (22 kB).
const FONT: &[u8] = include_bytes!("../../fonts/DejaVuSans-subset.ttf");

/// Registers the font once per process.
pub(super) fn register_font() -> Result<()> {
    static REGISTERED: OnceLock<bool> = OnceLock::new();
    let ok = *REGISTERED.get_or_init(|| {
        plotters::style::register_font("sans-serif", FontStyle::Normal, FONT).is_ok()
    });
    if ok {
        Ok(())
    } else {
        Err(Error::new(ErrorKind::Plot(
            "the bundled font DejaVuSans-subset.ttf does not load".into(),
        )))
    }
}

/// Draws with `draw` into an RGB buffer of `size` and writes it as PNG to `path`.
pub(super) fn write_png(
    path: &Path,
    size: (u32, u32),
    draw: impl FnOnce(DrawingArea<BitMapBackend<'_>, Shift>) -> std::result::Result<(), String>,
) -> Result<()> {
    let mut buffer = vec![255u8; size.0 as usize * size.1 as usize * 3];
    {
        let root = BitMapBackend::with_buffer(&mut buffer, size).into_drawing_area();
        draw(root).map_err(|e| Error::new(ErrorKind::Plot(format!("{}: {e}", path.display()))))?;
    }
    let file = std::fs::File::create(path).map_err(|e| Error::io("cannot write", path, e))?;
    let mut encoder = png::Encoder::new(std::io::BufWriter::new(file), size.0, size.1);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    let plot_error =
        |e: png::EncodingError| Error::new(ErrorKind::Plot(format!("{}: {e}", path.display())));
    let mut writer = encoder.write_header().map_err(plot_error)?;
    writer.write_image_data(&buffer).map_err(plot_error)?;
    writer.finish().map_err(plot_error)
}
