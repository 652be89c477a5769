//! The layer rule of `docs/design/architecture.md`: data flows one way, so no top-level module of
//! `src/` may import another that imports it back, directly or through others. Within a folder a
//! `mod.rs` and its children may use each other; between top-level modules nothing may loop.
//!
//! The test reads every `crate::…` path in the library's sources (comments left out), builds the
//! graph of top-level modules, and fails with the loop and the files that make it.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// Every `.rs` file under `dir`.
fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            sources(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The text without `//` comments and `/* */` blocks (string literals holding `//` are rare in
/// `use` lines and harmless: they can only hide a path, never invent one).
fn without_comments(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while !rest.is_empty() {
        if let Some(after) = rest.strip_prefix("//") {
            rest = after.find('\n').map_or("", |i| &after[i..]);
        } else if let Some(after) = rest.strip_prefix("/*") {
            rest = after.find("*/").map_or("", |i| &after[i + 2..]);
        } else {
            let c = rest.chars().next().unwrap();
            out.push(c);
            rest = &rest[c.len_utf8()..];
        }
    }
    out
}

fn is_ident(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// The top-level modules a source text names: `crate::m…` and each item of `crate::{a, b::c}`.
fn named_modules(text: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    let mut rest = text;
    while let Some(i) = rest.find("crate::") {
        // `crate::` not preceded by an identifier character (`mycrate::` is something else).
        let before = rest[..i].chars().next_back();
        rest = &rest[i + "crate::".len()..];
        if before.is_some_and(is_ident) {
            continue;
        }
        let rest_trim = rest.trim_start();
        if let Some(group) = rest_trim.strip_prefix('{') {
            // Items at the group's top nesting level.
            let mut depth = 0;
            let mut item_start = true;
            for (j, c) in group.char_indices() {
                match c {
                    '{' => depth += 1,
                    '}' if depth == 0 => break,
                    '}' => depth -= 1,
                    ',' if depth == 0 => item_start = true,
                    c if item_start && is_ident(c) => {
                        let name: String = group[j..].chars().take_while(|&c| is_ident(c)).collect();
                        out.insert(name);
                        item_start = false;
                    }
                    _ => {}
                }
            }
        } else {
            let name: String = rest_trim.chars().take_while(|&c| is_ident(c)).collect();
            if !name.is_empty() {
                out.insert(name);
            }
        }
    }
    out
}

/// Top-level module → (module it names → files that name it).
fn module_graph() -> BTreeMap<String, BTreeMap<String, Vec<String>>> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    sources(&src, &mut files);
    let mut graph: BTreeMap<String, BTreeMap<String, Vec<String>>> = BTreeMap::new();
    for file in files {
        let rel = file.strip_prefix(&src).unwrap();
        let first = rel.components().next().unwrap().as_os_str().to_string_lossy().into_owned();
        let top = first.strip_suffix(".rs").unwrap_or(&first).to_string();
        if top == "lib" || top == "main" {
            continue;
        }
        let text = without_comments(&std::fs::read_to_string(&file).unwrap());
        for m in named_modules(&text) {
            if m != top && (src.join(&m).is_dir() || src.join(format!("{m}.rs")).is_file()) {
                graph.entry(top.clone()).or_default().entry(m).or_default().push(rel.display().to_string());
            }
        }
        graph.entry(top).or_default();
    }
    graph
}

/// A loop through `start`, if the graph has one: the modules in order, `start` first.
fn find_loop(graph: &BTreeMap<String, BTreeMap<String, Vec<String>>>) -> Option<Vec<String>> {
    // Depth-first search with the path on a stack; a back edge to a module on the path closes a loop.
    fn visit(
        m: &str,
        graph: &BTreeMap<String, BTreeMap<String, Vec<String>>>,
        path: &mut Vec<String>,
        done: &mut BTreeSet<String>,
    ) -> Option<Vec<String>> {
        if let Some(i) = path.iter().position(|p| p == m) {
            return Some(path[i..].to_vec());
        }
        if done.contains(m) {
            return None;
        }
        path.push(m.to_string());
        for next in graph.get(m).into_iter().flat_map(|e| e.keys()) {
            if let Some(cycle) = visit(next, graph, path, done) {
                return Some(cycle);
            }
        }
        path.pop();
        done.insert(m.to_string());
        None
    }
    let mut done = BTreeSet::new();
    graph.keys().find_map(|m| visit(m, graph, &mut Vec::new(), &mut done))
}

#[test]
fn top_level_modules_do_not_import_each_other_in_a_loop() {
    let graph = module_graph();
    assert!(graph.len() >= 10, "read only {} top-level modules from src/", graph.len());
    if let Some(cycle) = find_loop(&graph) {
        let mut msg = format!("top-level modules import each other in a loop: {} → {}\n", cycle.join(" → "), cycle[0]);
        for (i, m) in cycle.iter().enumerate() {
            let next = &cycle[(i + 1) % cycle.len()];
            msg += &format!("  {m} → {next}: {}\n", graph[m][next].join(", "));
        }
        msg += "See docs/design/architecture.md for the layers.";
        panic!("{msg}");
    }
}

#[test]
fn the_checker_sees_imports_and_finds_loops() {
    let text = without_comments(
        "use crate::a::b;\n// use crate::commented;\nuse crate::{c::D, e, f::{g, h}};\nlet x = crate::i::j();\n/* crate::k */ mycrate::l;",
    );
    let found: Vec<String> = named_modules(&text).into_iter().collect();
    assert_eq!(found, ["a", "c", "e", "f", "i"]);

    let edge = |pairs: &[(&str, &str)]| {
        let mut g: BTreeMap<String, BTreeMap<String, Vec<String>>> = BTreeMap::new();
        for (a, b) in pairs {
            g.entry(a.to_string()).or_default().insert(b.to_string(), vec![]);
            g.entry(b.to_string()).or_default();
        }
        g
    };
    assert_eq!(find_loop(&edge(&[("a", "b"), ("b", "c"), ("a", "c")])), None);
    let cycle = find_loop(&edge(&[("a", "b"), ("b", "c"), ("c", "a")])).unwrap();
    assert_eq!(cycle.len(), 3);
}
