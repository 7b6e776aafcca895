//! `jacobian` names an unknown variable, one twice, and a fixed parameter: one error on each.

carvallo_macros::scene! {
    pub mod demo {
        model: demo,
        path: "../../fixtures/demo.ir",
        fixed: { R: 0.5 },
        jacobian: [x, speed, x, R],
    }
}

fn main() {}
