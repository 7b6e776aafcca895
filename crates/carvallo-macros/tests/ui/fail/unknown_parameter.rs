//! Fixing a name that is not a parameter of the model is an error on that name.

carvallo_macros::scene! {
    pub mod demo {
        model: demo,
        path: "../../fixtures/demo.ir",
        fixed: { R: 0.5, gravity: 9.81 },
    }
}

fn main() {}
