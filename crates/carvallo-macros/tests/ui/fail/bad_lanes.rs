//! `lanes` takes 2, 4, 8 or 16; any other value is an error on the value.

carvallo_macros::scene! {
    pub mod demo {
        model: demo,
        path: "../../fixtures/demo.ir",
        lanes: 3,
    }
}

fn main() {}
