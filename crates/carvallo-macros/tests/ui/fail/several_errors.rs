//! All problems of a scene are reported together, each on its own token.

carvallo_macros::scene! {
    pub mod demo {
        model: demo,
        path: "../../fixtures/demo.ir",
        fixed: { mu: 1.0, theta: 0.1, mu: 2.0 },
        outputs: [poly, nope],
    }
}

fn main() {}
