//! The symbolica license boundary (../shared/SYMBOLICA.md): the runtime, the concordance report,
//! the proc-macro, the IR, the CLI and the Python package must build and run without the computer-algebra crate. This test walks the
//! dependency graph recorded in the committed `Cargo.lock` from each of those packages and fails
//! if `symbolica` (or its arithmetic crate `numerica`) is reachable.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// Package name -> names of its dependencies, from `Cargo.lock`.
fn lock_graph() -> BTreeMap<String, Vec<String>> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let text = std::fs::read_to_string(root.join("Cargo.lock")).expect("Cargo.lock is committed");
    let lock: toml::Value = toml::from_str(&text).expect("Cargo.lock is valid toml");
    let mut graph = BTreeMap::new();
    for pkg in lock["package"].as_array().expect("package array") {
        let name = pkg["name"].as_str().expect("package name").to_string();
        let deps = pkg
            .get("dependencies")
            .and_then(|d| d.as_array())
            .map(|d| {
                d.iter()
                    .filter_map(|x| x.as_str())
                    .map(|x| x.split(' ').next().unwrap_or(x).to_string())
                    .collect()
            })
            .unwrap_or_default();
        graph.entry(name).or_insert_with(Vec::new).extend::<Vec<String>>(deps);
    }
    graph
}

fn reachable(graph: &BTreeMap<String, Vec<String>>, from: &str) -> BTreeSet<String> {
    let mut seen = BTreeSet::new();
    let mut stack = vec![from.to_string()];
    while let Some(p) = stack.pop() {
        if seen.insert(p.clone()) {
            if let Some(deps) = graph.get(&p) {
                stack.extend(deps.iter().cloned());
            }
        }
    }
    seen
}

#[test]
fn user_facing_crates_do_not_depend_on_symbolica() {
    let graph = lock_graph();
    for krate in [
        "carvallo",
        "carvallo-report",
        "carvallo-ir",
        "carvallo-macros",
        "carvallo-cli",
        "carvallo-py",
    ] {
        assert!(graph.contains_key(krate), "{krate} is missing from Cargo.lock");
        let deps = reachable(&graph, krate);
        for forbidden in ["symbolica", "numerica"] {
            assert!(
                !deps.contains(forbidden),
                "{krate} depends (transitively) on {forbidden}; only codegen/xtask may"
            );
        }
    }
}

#[test]
fn the_python_package_links_pyo3_and_the_runtime() {
    // Guards the boundary test above for carvallo-py: its graph does hold its real dependencies.
    let deps = reachable(&lock_graph(), "carvallo-py");
    for needed in ["carvallo", "pyo3", "numpy"] {
        assert!(deps.contains(needed), "carvallo-py does not reach {needed}");
    }
}

#[test]
fn the_derivation_side_does_use_symbolica() {
    // Guards the test above against a graph that lost its edges.
    let graph = lock_graph();
    assert!(reachable(&graph, "carvallo-codegen").contains("symbolica"));
    assert!(reachable(&graph, "xtask").contains("symbolica"));
}

#[test]
fn the_library_does_not_depend_on_the_report() {
    // Layers run numerics -> models -> report -> CLI: `carvallo` must not reach the concordance.
    let graph = lock_graph();
    assert!(reachable(&graph, "carvallo-report").contains("carvallo"));
    assert!(!reachable(&graph, "carvallo").contains("carvallo-report"));
}
