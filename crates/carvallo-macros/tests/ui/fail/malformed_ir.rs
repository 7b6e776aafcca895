//! An IR file that does not parse is an error on the `path` literal, with the file's line and column.

carvallo_macros::scene! {
    pub mod broken {
        model: malformed,
        path: "../../fixtures/malformed.ir",
    }
}

fn main() {}
