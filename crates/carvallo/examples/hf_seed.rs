use carvallo::whipple::steady_turn::hands_free::HandsFree;
use carvallo::whipple::steady_turn::TurnSolver;
use carvallo::whipple::WhippleParams;
fn main() {
    let p = WhippleParams::benchmark();
    let solver = TurnSolver::new(&p).unwrap();
    let hf = HandsFree::new(&solver);
    let args: Vec<f64> = std::env::args().skip(1).map(|a| a.parse().unwrap()).collect();
    for s in args.chunks(3) {
        let f = hf.through([s[0], s[1], s[2]]).unwrap();
        println!("seed {:?}: {} points end {:?}", s, f.points.len(), f.end);
        for sp in &f.special {
            println!(
                "  {:?} {:?}",
                sp,
                f.points[match *sp {
                    carvallo::whipple::steady_turn::hands_free::Special::SpeedFold(k)
                    | carvallo::whipple::steady_turn::hands_free::Special::LeanFold(k)
                    | carvallo::whipple::steady_turn::hands_free::Special::Branch(k)
                    | carvallo::whipple::steady_turn::hands_free::Special::StabilityChange(k) => k,
                }]
            );
        }
        let (a, b) = (f.points[0], f.points[f.points.len() - 1]);
        println!("  first {:?}\n  last {:?}", a, b);
        for q in f.points.iter().step_by(10) {
            println!("   {:.4} {:.4} {:.4} {}", q.speed, q.lean, q.steer, q.stable);
        }
    }
}
