//! The one drawing stack of every figure (the design's report and `plot` of recorded data): panels
//! of series laid out in rows, one series style ([`Style`]: how a series is drawn and its legend
//! swatch, from the same code) and one legend placement ([`legend`](render::legend): beside the plotting area, so it
//! never covers data), written as PNG and SVG (plotters; the bundled DejaVu Sans font is rasterised by
//! ab_glyph, so no system font library is involved).

mod panel;
mod render;
mod style;

use std::path::{Path, PathBuf};
use std::sync::Once;

use plotters::coord::Shift;
use plotters::prelude::*;

pub(crate) use panel::{with_unit, Panel, Series};
pub(crate) use render::tick;
use render::{draw_panel, legend_width};
pub(crate) use style::{
    Style, ESTIMATE_COLOR, MARK_COLOR, NOISE_COLOR, PALETTE, REFUSED_COLOR, SATURATED_COLOR, TRUE_COLOR,
};

/// Why a figure could not be written.
#[derive(Debug, thiserror::Error)]
pub enum PlotError {
    /// plotters failed to draw (its errors are generic over the backend; their text is kept).
    #[error("{}: cannot draw: {message}", file.display())]
    Draw {
        /// The figure.
        file: PathBuf,
        /// plotters' message.
        message: String,
    },
    /// The file or its folder could not be written.
    #[error("{}: {source}", path.display())]
    Io {
        /// The file or folder.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
}

const FONT: &str = "sans-serif";
static REGISTER_FONT: Once = Once::new();

fn register_font() {
    REGISTER_FONT.call_once(|| {
        let bytes: &'static [u8] = include_bytes!("../../../assets/DejaVuSans.ttf");
        // The font is bundled and valid; a failure here would only lose the text of the plots.
        let _ = plotters::style::register_font(FONT, FontStyle::Normal, bytes);
    });
}

/// A figure: rows of panels, each row split evenly among its panels (a row of one spans the width).
pub(crate) struct Figure {
    pub rows: Vec<Vec<Panel>>,
    /// Width of a panel's plotting part in a row of one (legend excluded), in pixels.
    pub panel_width: u32,
    /// Height of a row, in pixels.
    pub row_height: u32,
}

impl Figure {
    /// Rows of `per_row` panels (the last may hold fewer), each panel 560 × 380 px before its legend.
    pub(crate) fn grid(panels: Vec<Panel>, per_row: usize) -> Self {
        let mut rows: Vec<Vec<Panel>> = Vec::new();
        for panel in panels {
            match rows.last_mut() {
                Some(row) if row.len() < per_row.max(1) => row.push(panel),
                _ => rows.push(vec![panel]),
            }
        }
        Figure {
            rows,
            panel_width: 560,
            row_height: 380,
        }
    }

    fn size(&self, legend_width: u32) -> (u32, u32) {
        let columns = self.rows.iter().map(Vec::len).max().unwrap_or(1).max(1) as u32;
        (
            (self.panel_width + legend_width) * columns,
            self.row_height * self.rows.len().max(1) as u32,
        )
    }

    fn draw<DB: DrawingBackend>(&self, root: DrawingArea<DB, Shift>, legend_width: u32) -> Result<(), String> {
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        for (row_area, row) in root.split_evenly((self.rows.len().max(1), 1)).iter().zip(&self.rows) {
            for (area, panel) in row_area.split_evenly((1, row.len().max(1))).iter().zip(row) {
                draw_panel(area, panel, legend_width)?;
            }
        }
        root.present().map_err(|e| e.to_string())
    }
}

/// Writes `figure` as `<prefix>.png` and `<prefix>.svg`. Both are drawn before either replaces a file
/// (the PNG through a temporary file beside it, the SVG in memory), so a failure to draw writes
/// nothing.
pub(crate) fn write_figure(prefix: &Path, figure: &Figure) -> Result<Vec<PathBuf>, PlotError> {
    register_font();
    let legend_width = legend_width(figure);
    let size = figure.size(legend_width);
    let stem = prefix
        .file_name()
        .map_or(String::new(), |n| n.to_string_lossy().into_owned());
    let folder = match prefix.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_owned(),
        _ => PathBuf::from("."),
    };
    let (png, svg) = (with_suffix(prefix, "png"), with_suffix(prefix, "svg"));
    let mut svg_text = String::new();
    figure
        .draw(
            SVGBackend::with_string(&mut svg_text, size).into_drawing_area(),
            legend_width,
        )
        .map_err(|message| PlotError::Draw {
            file: svg.clone(),
            message,
        })?;
    crate::output::remove_stale_temporaries(&folder, &format!(".{stem}.tmp"), ".png");
    let temporary = folder.join(format!(".{stem}.tmp{}.png", std::process::id()));
    let drawn = figure
        .draw(BitMapBackend::new(&temporary, size).into_drawing_area(), legend_width)
        .map_err(|message| PlotError::Draw {
            file: png.clone(),
            message,
        });
    let written = drawn.and_then(|()| {
        crate::output::write_atomically(&svg, svg_text.as_bytes()).map_err(|source| PlotError::Io {
            path: svg.clone(),
            source,
        })?;
        std::fs::rename(&temporary, &png).map_err(|source| PlotError::Io {
            path: png.clone(),
            source,
        })
    });
    if written.is_err() {
        let _ = std::fs::remove_file(&temporary);
    }
    written?;
    Ok(vec![png, svg])
}

/// `<prefix>.<extension>` (`with_extension` would replace a dot already in the prefix's name).
pub(crate) fn with_suffix(prefix: &Path, extension: &str) -> PathBuf {
    let mut name = prefix.as_os_str().to_owned();
    name.push(format!(".{extension}"));
    PathBuf::from(name)
}

/// Every `stride`-th of `count` items so that at most `most` are drawn (a dot per window would make
/// an SVG grow with the data: 184 MB at 10⁶ windows), and how to say so.
pub(crate) fn thinning(count: usize, most: usize) -> usize {
    count.div_ceil(most.max(1)).max(1)
}
