//! A model with no `generated/<model>.ir` is an error on the model name.

carvallo_macros::scene! {
    pub mod nowhere {
        model: no_such_model,
    }
}

fn main() {}
