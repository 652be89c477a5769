//! `global_settings { }`.

use super::Parser;
use crate::pov::ast::{GlobalItem, Stmt};
use crate::pov::lexer::TokenKind;
use crate::pov::source::PResult;

const GLOBAL: &[&str] = &[
    "assumed_gamma",
    "max_trace_level",
    "ambient_light",
    "noise_generator",
    "number_of_waves",
    "irid_wavelength",
    "adc_bailout",
    "charset",
    "hf_gray_16",
    "max_intersections",
    "radiosity",
    "photons",
    "subsurface",
    "mm_per_unit",
];
/// `global_settings` blocks of rendering features strahl does not model: skipped, noted.
const GLOBAL_UNMODELLED: &[&str] = &["radiosity", "photons", "subsurface"];

impl Parser<'_, '_> {
    pub(super) fn global_settings(&mut self) -> PResult<Stmt> {
        let kw = self.bump().span;
        self.open_block("global_settings", kw)?;
        let mut items = Vec::new();
        while !self.at_block_end() {
            let item = match self.peek_ident().as_deref() {
                Some("assumed_gamma") => {
                    self.bump();
                    GlobalItem::AssumedGamma(self.expr()?)
                }
                Some("max_trace_level") => {
                    self.bump();
                    GlobalItem::MaxTraceLevel(self.expr()?)
                }
                Some("ambient_light") => {
                    self.bump();
                    GlobalItem::AmbientLight(self.color()?)
                }
                Some("noise_generator") => {
                    self.bump();
                    GlobalItem::NoiseGenerator(self.expr()?)
                }
                Some("number_of_waves") => {
                    self.bump();
                    GlobalItem::NumberOfWaves(self.expr()?)
                }
                Some("irid_wavelength") => {
                    self.bump();
                    GlobalItem::IridWavelength(self.color()?)
                }
                Some("adc_bailout") => {
                    self.bump();
                    GlobalItem::AdcBailout(self.expr()?)
                }
                Some(w) if GLOBAL_UNMODELLED.contains(&w) => {
                    self.skip_unmodelled(w)?;
                    continue;
                }
                // Settings about files and old limits that change nothing strahl draws: the
                // `charset` of strings (strahl reads UTF-8, a superset of ascii), 16-bit grey
                // output for height fields, the obsolete `max_intersections`, and the
                // subsurface scale `mm_per_unit`.
                Some("charset") => {
                    self.bump();
                    self.bump();
                    continue;
                }
                Some("hf_gray_16") => {
                    self.bump();
                    if !matches!(self.peek().kind, TokenKind::Ident(_) | TokenKind::Punct('}')) {
                        self.expr()?;
                    } else if matches!(
                        self.peek_ident().as_deref(),
                        Some("on" | "off" | "true" | "false" | "yes" | "no")
                    ) {
                        self.bump();
                    }
                    continue;
                }
                Some("max_intersections" | "mm_per_unit") => {
                    self.bump();
                    self.expr()?;
                    continue;
                }
                _ => return Err(self.unknown_in("global_settings", GLOBAL)),
            };
            items.push(item);
        }
        self.close_block("global_settings", kw)?;
        Ok(Stmt::GlobalSettings { items, span: kw })
    }
}
