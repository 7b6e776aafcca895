use carvallo::whipple::feedback::{closed_loop_window_all_roots, closed_loop_window_of, Gains};
use carvallo::whipple::{Whipple, WhippleParams};
use std::hint::black_box;
fn main() {
    let w = Whipple::new(WhippleParams::benchmark());
    let g = Gains::balance_assist(10.0);
    let n: usize = std::env::args().nth(1).map_or(200_000, |s| s.parse().unwrap());
    let p = w.closed_loop_poly(&g);
    let t = std::time::Instant::now();
    let mut s = 0.0;
    for _ in 0..n {
        s += closed_loop_window_of(black_box(&p), 0.0, 10.0).stable.len() as f64;
    }
    let e = t.elapsed().as_secs_f64();
    let t2 = std::time::Instant::now();
    for _ in 0..n {
        s += w.closed_loop_poly(black_box(&g)).coeffs[0][0];
    }
    let e2 = t2.elapsed().as_secs_f64();
    println!("window_of {:.1} ns; poly {:.1} ns; {s}", e / n as f64 * 1e9, e2 / n as f64 * 1e9);
    println!("{:?}", closed_loop_window_of(&p, 0.0, 10.0));
    let t3 = std::time::Instant::now();
    for _ in 0..n {
        s += closed_loop_window_all_roots(black_box(&p), 0.0, 10.0).stable.len() as f64;
    }
    println!("all_roots {:.1} ns {s}", t3.elapsed().as_secs_f64() / n as f64 * 1e9);
    println!("{:?}", closed_loop_window_all_roots(&p, 0.0, 10.0));
}
#[allow(dead_code)]
fn unused() {}
