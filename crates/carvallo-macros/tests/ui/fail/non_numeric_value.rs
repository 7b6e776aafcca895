//! Fixed values must be finite numeric literals; each bad value is its own error.

carvallo_macros::scene! {
    pub mod demo {
        model: demo,
        path: "../../fixtures/demo.ir",
        fixed: { R: "half", g: 1e999 },
    }
}

fn main() {}
