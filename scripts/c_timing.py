"""The C timing loop the peer scripts compile beside the code they time (scripts/pydy_c_peer.py,
scripts/casadi_peer.py), written once: the timer of our own C peer
(crates/carvallo-cli/src/bench/peer.rs) and of `carvallo bench` (`time_ns`): the timed call
between compiler barriers that hold its pointers, the smallest of five means over slices of at
least `min_time / 5` seconds, the number of calls per slice grown until a slice lasts that
long."""

from __future__ import annotations

# `now()`: seconds of the monotonic clock. Needs <time.h>.
NOW = r"""
static double now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}
"""


def timing_loop(call: str, pointers: list[str], min_time: str = "min_time",
                result: str = "best") -> str:
    """C statements that time the statement `call` (e.g. `rhs(x, c, xd);`) and leave the
    nanoseconds per call in a new `double` named `result`; `pointers` are the variables the
    barriers around every call hold (the call's inputs and outputs), `min_time` the C
    expression of the seconds to spend. Needs `now()` ([`NOW`]) and <math.h>'s INFINITY."""
    if not pointers:
        raise ValueError("the barriers need at least one pointer")
    barrier = ('__asm__ volatile("" : : '
               + ", ".join(f'"r"({p})' for p in pointers) + ' : "memory");')
    return f"""
    double {result} = INFINITY;
    {{
        double slice = ({min_time}) / 5.0;
        long n = 1;
        int rounds = 0;
        while (rounds < 5) {{
            double t0 = now();
            for (long r = 0; r < n; r++) {{
                {barrier}
                {call}
                {barrier}
            }}
            double dt = now() - t0;
            if (dt >= slice) {{
                if (dt * 1e9 / (double)n < {result}) {result} = dt * 1e9 / (double)n;
                rounds++;
            }} else if (dt <= 0.0) {{
                n *= 16;
            }} else {{
                double g = 1.2 * slice / dt;
                n = (long)((double)n * (g < 16.0 ? g : 16.0)) + 1;
            }}
        }}
    }}
"""
