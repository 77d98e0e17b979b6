//! Helpers shared by the integration tests that draw random cases
//! (reference_diff, line_reference_diff, vertex_batch, lines, pipeline,
//! pixels).
#![allow(dead_code)]

/// A small deterministic generator (a 64-bit LCG, upper bits): the same
/// seed gives the same cases on every machine.
pub struct Rng(pub u64);

impl Rng {
    pub fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        self.0 >> 33
    }
    pub fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
    pub fn chance(&mut self, percent: u64) -> bool {
        self.below(100) < percent
    }
    pub fn unit(&mut self) -> f32 {
        self.next() as f32 / (1u64 << 31) as f32
    }
    /// A float in [0, 1) from the state's top 24 bits.
    pub fn f24(&mut self) -> f32 {
        (self.next() >> 7) as f32 / (1u64 << 24) as f32
    }
    /// A multiple of 1/4 in [lo, hi).
    pub fn quarter(&mut self, lo: f32, hi: f32) -> f32 {
        lo + self.below(((hi - lo) * 4.0) as u64) as f32 / 4.0
    }
    pub fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.unit()
    }
    pub fn pick<T: Copy>(&mut self, v: &[T]) -> T {
        v[self.below(v.len() as u64) as usize]
    }
}
