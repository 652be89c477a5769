//! Image blocks → `ImageMapDesc`: the file found as `#include` finds files (as written, the
//! scene's folder, then the include path, as `height_field` does), decoded by
//! `crate::image_file`, and how its values become working colours.

use std::sync::Arc;

use super::Lowerer;
use crate::desc::{ImageMapDesc, ImageMapping};
use crate::pov::source::{Diag, PResult, Span};

/// Largest image side read.
const MAX_SIDE: usize = 16384;

/// The bitmap modifiers of an image block as written.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct ImageOptions {
    pub mapping: ImageMapping,
    pub interpolate: u32,
    pub once: bool,
    /// `None`: the block's default (index for `bump_map`, colour otherwise).
    pub use_index_set: Option<bool>,
    pub use_alpha: bool,
    pub filter: Vec<(Option<usize>, f64)>,
    pub transmit: Vec<(Option<usize>, f64)>,
    /// `gamma G` written in the block: the file's values are raised to G rather than
    /// sRGB-decoded.
    pub file_gamma: Option<f64>,
}

impl Default for ImageOptions {
    fn default() -> Self {
        ImageOptions {
            mapping: ImageMapping::Planar,
            interpolate: 0,
            once: false,
            use_index_set: None,
            use_alpha: false,
            filter: Vec::new(),
            transmit: Vec::new(),
            file_gamma: None,
        }
    }
}

impl Lowerer<'_> {
    /// Finds and decodes the image of a `word` block (`image_map`, `bump_map`, `image_pattern`).
    pub(crate) fn image_map_desc(
        &mut self,
        word: &str,
        format: Option<&str>,
        name: &str,
        span: Span,
        opts: ImageOptions,
    ) -> PResult<Arc<ImageMapDesc>> {
        let format = format.or_else(|| crate::image_file::type_from_extension(name)).unwrap_or("sys").to_string();
        let path = if std::path::Path::new(name).is_file() {
            std::path::PathBuf::from(name)
        } else {
            self.files.data_path(name, false).ok().filter(|p| p.is_file()).ok_or_else(|| {
                Diag::new(
                    span,
                    format!(
                        "{word} image \"{name}\" not found (searched as written, the scene's folder and the include \
                         path)"
                    ),
                )
            })?
        };
        let bytes = std::fs::read(&path)
            .map_err(|e| Diag::new(span, format!("cannot read {word} image \"{}\": {e}", path.display())))?;
        let image = crate::image_file::read_image(&format, &bytes, MAX_SIDE)
            .map_err(|m| Diag::new(span, format!("{word}: \"{}\" as {format}: {m}", path.display())))?;
        // POV-Ray 3.7 decodes the file's values by its gamma (sRGB unless `gamma` says) into
        // linear light and then into the scene's working space (`assumed_gamma`); a legacy
        // scene (no gamma handling) uses them as stored. The global settings read so far
        // decide (they come first in the sample scenes).
        let decode_gamma = self.scene.output_gamma();
        let use_index = opts.use_index_set.unwrap_or(word == "bump_map");
        Ok(Arc::new(ImageMapDesc {
            file: path.display().to_string(),
            format,
            image: Arc::new(image),
            mapping: opts.mapping,
            interpolate: opts.interpolate,
            once: opts.once,
            use_index,
            use_alpha: opts.use_alpha,
            filter: opts.filter,
            transmit: opts.transmit,
            decode_gamma,
            file_gamma: opts.file_gamma,
        }))
    }
}
