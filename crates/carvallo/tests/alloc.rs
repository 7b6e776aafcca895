//! A simulation kept to its end allocates nothing: `WhippleNonlinear::simulate_final` (the
//! runs of `simulate --batch` and Python's `simulate_many`) by every method, with stop
//! conditions, counted by a global allocator that counts the allocations of the calling thread.

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

use carvallo::numerics::integrate::{Grid, Integration, Method};
use carvallo::whipple::nonlinear::{Stop, WhippleNonlinear};
use carvallo::whipple::WhippleParams;

struct Counting;

thread_local! {
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let _ = ALLOCATIONS.try_with(|c| c.set(c.get() + 1));
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

fn allocations() -> usize {
    ALLOCATIONS.with(Cell::get)
}

#[test]
fn a_final_only_simulation_allocates_nothing() {
    let bike = WhippleNonlinear::new(WhippleParams::benchmark());
    let stops = [Stop::parse("lean=±0.5").expect("stop"), Stop::parse("pitch=1").expect("stop")];
    let grid = Grid::new(3.0, 1e-3, usize::MAX).expect("grid");
    for how in [
        Integration::RK4,
        Integration::adaptive(Method::Dopri5, 1e-9, 1e-12),
        Integration::adaptive(Method::Dop853, 1e-12, 1e-15),
        Integration::adaptive(Method::Vern9, 1e-12, 1e-15),
    ] {
        for speed in [4.6, 2.0] {
            let start = bike.initial_state(speed, 0.05).expect("state");
            let before = allocations();
            let end = bike.simulate_final(start, &grid, &how, &stops).expect("run");
            let during = allocations() - before;
            assert_eq!(during, 0, "{} at {speed} m/s: {during} allocations", how.method);
            assert!(end.stats.steps > 0);
            assert_eq!(end.event.is_some(), speed == 2.0, "{end:?}");
        }
    }
}
