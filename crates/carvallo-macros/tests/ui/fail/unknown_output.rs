//! Selecting a name that is not an output of the model is an error on that name.

carvallo_macros::scene! {
    pub mod demo {
        model: demo,
        path: "../../fixtures/demo.ir",
        outputs: [trig, energy],
    }
}

fn main() {}
