//! SplitMix64: the one seeded generator of the workspace's sample points, so that they are the
//! same on every platform and no random-number crate is needed at run time.

/// The SplitMix64 generator (Steele, Lea and Flood 2014) with its state as the one field.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SplitMix64(pub u64);

impl SplitMix64 {
    /// The increment of the state per draw.
    const GAMMA: u64 = 0x9E37_79B9_7F4A_7C15;

    /// Skips `n` draws in constant time: the state is a counter advanced by a constant per draw,
    /// so the stream after `skip(n)` is the stream after `n` calls of [`Self::next_u64`].
    pub fn skip(&mut self, n: u64) {
        self.0 = self.0.wrapping_add(n.wrapping_mul(Self::GAMMA));
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(Self::GAMMA);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A uniform number in $[0, 1)$ (the top 53 bits of [`Self::next_u64`]).
    pub fn next_unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A uniform number in $[lo, hi)$.
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next_unit()
    }

    /// A uniform number in $(0, 1]$ (never zero: a safe argument of a logarithm).
    pub fn next_unit_nonzero(&mut self) -> f64 {
        ((self.next_u64() >> 11) + 1) as f64 / (1u64 << 53) as f64
    }

    /// Two independent standard normal numbers (Box–Muller from two draws of
    /// [`Self::next_unit_nonzero`]).
    pub fn normal_pair(&mut self) -> (f64, f64) {
        let (u1, u2) = (self.next_unit_nonzero(), self.next_unit_nonzero());
        let r = (-2.0 * u1.ln()).sqrt();
        let t = std::f64::consts::TAU * u2;
        (r * t.cos(), r * t.sin())
    }

    /// `x` scaled by a uniform factor in $[1 - r, 1 + r]$, `r = spread` (one draw of
    /// [`Self::next_unit`]).
    pub fn scale(&mut self, x: f64, spread: f64) -> f64 {
        x * (1.0 + spread * (2.0 * self.next_unit() - 1.0))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn skipping_equals_drawing() {
        for n in [0u64, 1, 2, 25, 1000] {
            let (mut a, mut b) = (SplitMix64(12345), SplitMix64(12345));
            for _ in 0..n {
                a.next_u64();
            }
            b.skip(n);
            assert_eq!(a, b);
            assert_eq!(a.next_u64(), b.next_u64());
        }
    }

    #[test]
    fn first_outputs_of_seed_zero_are_the_published_ones() {
        // Reference values of SplitMix64 from seed 0 (Vigna's splitmix64.c).
        let mut rng = SplitMix64(0);
        assert_eq!(rng.next_u64(), 0xE220_A839_7B1D_CDAF);
        assert_eq!(rng.next_u64(), 0x6E78_9E6A_A1B9_65F4);
    }

    #[test]
    fn uniform_stays_in_range() {
        let mut rng = SplitMix64(7);
        assert!((0..1000).map(|_| rng.uniform(-2.0, 3.0)).all(|x| (-2.0..3.0).contains(&x)));
    }
}
