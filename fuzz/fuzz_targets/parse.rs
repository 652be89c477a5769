//! Fuzzes the whole loader (lexer → parser → lower) and the scene build on arbitrary bytes:
//! neither may panic, whatever the input. Errors are fine; they are values.
#![no_main]

use std::path::PathBuf;
use std::sync::OnceLock;

use libfuzzer_sys::fuzz_target;
use strahl::pov::{load_scene, IncludePath};
use strahl::scene::build::{AccelKind, Scene};

/// One scratch file per fuzzing process: `load_scene` reads files (it follows `#include`), and
/// there is no string entry point that also lowers.
fn scratch() -> &'static PathBuf {
    static PATH: OnceLock<PathBuf> = OnceLock::new();
    PATH.get_or_init(|| {
        let dir = std::env::temp_dir().join(format!("strahl-fuzz-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("create scratch dir");
        dir.join("input.pov")
    })
}

/// The shipped includes (`colors.inc`, `textures.inc`), so the seed corpus resolves them.
fn include_path() -> IncludePath {
    IncludePath { dirs: vec![PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../scenes/include"))] }
}

fuzz_target!(|data: &[u8]| {
    let path = scratch();
    std::fs::write(path, data).expect("write scratch file");
    if let Ok(desc) = load_scene(path, &include_path()) {
        let _ = Scene::build(&desc, desc.camera.location, AccelKind::Bvh);
    }
});
