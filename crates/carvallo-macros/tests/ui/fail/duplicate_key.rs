//! A key given twice is an error on its second occurrence.

carvallo_macros::scene! {
    pub mod demo {
        model: demo,
        path: "../../fixtures/demo.ir",
        outputs: [trig],
        outputs: [poly],
    }
}

fn main() {}
