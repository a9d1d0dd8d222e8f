//! The last `N` samples, always readable as one contiguous array, oldest first.
//!
//! Every sample is stored twice, at slot `s` of two consecutive copies of an `N`-slot buffer, so the
//! window `[next, next + N)` of the flattened `2N` slots is the last `N` samples in order wherever
//! the write position `next` is. A push is two stores per value and an index update; nothing is
//! shifted, and the dot products read the window at fixed offsets.

/// What a window can hold: a copyable value with a zero to fill an empty window with (the floats of
/// [`crate::Scalar`], and the raw integer samples of the fixed-point map, [`crate::fixed`]).
pub trait Stored: Copy {
    /// The value an empty window holds.
    const ZERO: Self;
}

impl Stored for f32 {
    const ZERO: Self = 0.0;
}

impl Stored for f64 {
    const ZERO: Self = 0.0;
}

impl Stored for i32 {
    const ZERO: Self = 0;
}

/// One sampling instant: the measured outputs and the applied inputs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample<T, const NY: usize, const NU: usize> {
    /// `y(k)`.
    pub y: [T; NY],
    /// `u(k)`.
    pub u: [T; NU],
}

/// The last `N` samples.
#[derive(Clone, Debug)]
pub struct Window<T, const N: usize, const NY: usize, const NU: usize> {
    copies: [[Sample<T, NY, NU>; N]; 2],
    /// Slot of the next write, which is also the oldest sample of the window.
    next: usize,
    /// Samples stored since the last reset, up to `N`.
    filled: usize,
}

impl<T: Stored, const N: usize, const NY: usize, const NU: usize> Window<T, N, NY, NU> {
    /// An empty window.
    #[must_use]
    pub const fn new() -> Self {
        let zero = Sample {
            y: [T::ZERO; NY],
            u: [T::ZERO; NU],
        };
        Window {
            copies: [[zero; N]; 2],
            next: 0,
            filled: 0,
        }
    }

    /// Stores `sample` as the newest, dropping the oldest once `N` are held.
    #[inline(always)]
    pub fn push(&mut self, sample: Sample<T, NY, NU>) {
        let slot = self.next;
        let [first, second] = &mut self.copies;
        // `next < N` always holds; `get_mut` keeps a panic path out of the firmware regardless.
        if let (Some(a), Some(b)) = (first.get_mut(slot), second.get_mut(slot)) {
            *a = sample;
            *b = sample;
        }
        // By sign masks rather than comparisons: the same instructions at every write position, also
        // on cores without conditional execution (Cortex-M0). `slot < N` and `filled <= N` hold.
        let stays = ((N - 1 - slot) as isize).wrapping_neg() >> (isize::BITS - 1); // −1 unless slot = N − 1
        self.next = (slot + 1) & stays as usize;
        let full = ((N - 1) as isize - self.filled as isize) >> (isize::BITS - 1); // −1 once filled = N
        self.filled = self.filled.wrapping_add(1).wrapping_add(full as usize);
    }

    /// Forgets every sample.
    pub fn clear(&mut self) {
        self.next = 0;
        self.filled = 0;
    }

    /// `true` once `N` samples are held.
    #[must_use]
    pub fn is_full(&self) -> bool {
        self.filled >= N
    }

    /// The last `N` samples, oldest first, or `None` before `N` have arrived.
    #[inline(always)]
    #[must_use]
    pub fn samples(&self) -> Option<&[Sample<T, NY, NU>; N]> {
        if !self.is_full() {
            return None;
        }
        let flat = self.copies.as_flattened();
        flat.get(self.next..self.next + N)?.try_into().ok()
    }
}

impl<T: Stored, const N: usize, const NY: usize, const NU: usize> Default for Window<T, N, NY, NU> {
    fn default() -> Self {
        Self::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn holds_the_last_n_samples_oldest_first_at_every_write_position() {
        let mut window: Window<f64, 3, 1, 1> = Window::new();
        for k in 0..10 {
            window.push(Sample {
                y: [k as f64],
                u: [-(k as f64)],
            });
            let expected: Option<Vec<f64>> = (k >= 2).then(|| (k - 2..=k).map(|j| j as f64).collect());
            let got = window.samples().map(|s| s.iter().map(|s| s.y[0]).collect::<Vec<_>>());
            assert_eq!(got, expected, "k = {k}");
        }
        window.clear();
        assert!(window.samples().is_none() && !window.is_full());
    }
}
