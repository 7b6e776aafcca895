//! A scene that does not parse is an error on the first unexpected token.

carvallo_macros::scene! {
    pub mod demo {
        model demo,
    }
}

fn main() {}
