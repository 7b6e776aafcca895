use carvallo::whipple::feedback::{closed_loop_window_of, Gains};
use carvallo::whipple::{Whipple, WhippleParams};
fn main() {
    let w = Whipple::new(WhippleParams::benchmark());
    let p = w.closed_loop_poly(&Gains::balance_assist(10.0));
    println!("{:?}", closed_loop_window_of(&p, 0.0, 10.0));
}
