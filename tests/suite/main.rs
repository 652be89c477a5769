//! Every integration test that needs only the Rust toolchain, in one binary: one link of the
//! library instead of one per file (`cargo test --release` compiles in half the time). Each module
//! was a test file of its own and keeps its name, so `cargo test --release --test suite reference`
//! runs what `--test reference` ran. Tests that need Debian packages are in `tests/packages`.

mod common;

mod cli;
mod extremes;
mod far;
mod farm;
mod fly;
mod golden;
mod language;
mod layers;
mod pov_parse;
mod precision;
mod properties;
mod reference;
mod reproject;
mod samples;
mod scaling;
mod tradeoff;
