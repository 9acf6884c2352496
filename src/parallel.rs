//! Data parallelism for the model: rayon's parallel iterators where there
//! are threads; in a browser's WebAssembly, which has none (there rayon runs
//! every job on the calling thread anyway, and the page shares a heavy job
//! among Web Workers instead: see [`crate::scene::parts`]), plain iterators
//! with the same names. Every parallel map of the model ends in an ordered
//! `collect`, so both give the same values; the plain ones keep rayon's
//! machinery, about 200 KB, out of the WebAssembly module.

#[cfg(not(all(target_family = "wasm", target_os = "unknown")))]
pub use rayon::join;

/// The parallel iterators: rayon's.
#[cfg(not(all(target_family = "wasm", target_os = "unknown")))]
pub mod prelude {
    pub use rayon::prelude::*;
}

/// Runs `f` on a worker of the thread pool (so that the parallel steps
/// inside it are joins among the pool's workers rather than jobs handed in
/// from outside and waited for).
#[cfg(not(all(target_family = "wasm", target_os = "unknown")))]
pub fn on_pool<R: Send>(f: impl FnOnce() -> R + Send) -> R {
    rayon::scope(|_| f())
}

/// Runs `a` and then `b` (no threads).
#[cfg(all(target_family = "wasm", target_os = "unknown"))]
pub fn join<A: FnOnce() -> RA, B: FnOnce() -> RB, RA, RB>(a: A, b: B) -> (RA, RB) {
    (a(), b())
}

/// Runs `f` (no threads).
#[cfg(all(target_family = "wasm", target_os = "unknown"))]
pub fn on_pool<R>(f: impl FnOnce() -> R) -> R {
    f()
}

/// Sequential iterators under the names of rayon's parallel ones (no threads).
#[cfg(all(target_family = "wasm", target_os = "unknown"))]
pub mod prelude {
    /// `par_iter()`: the items by reference, in order.
    pub trait IntoParallelRefIterator<'a> {
        /// The iterator.
        type Iter: Iterator;
        /// The items by reference.
        fn par_iter(&'a self) -> Self::Iter;
    }

    impl<'a, T: 'a> IntoParallelRefIterator<'a> for [T] {
        type Iter = std::slice::Iter<'a, T>;
        fn par_iter(&'a self) -> Self::Iter {
            self.iter()
        }
    }

    impl<'a, T: 'a> IntoParallelRefIterator<'a> for Vec<T> {
        type Iter = std::slice::Iter<'a, T>;
        fn par_iter(&'a self) -> Self::Iter {
            self.iter()
        }
    }

    /// `into_par_iter()`: the items, in order.
    pub trait IntoParallelIterator {
        /// The iterator.
        type Iter: Iterator;
        /// The items.
        fn into_par_iter(self) -> Self::Iter;
    }

    impl<I: IntoIterator> IntoParallelIterator for I {
        type Iter = I::IntoIter;
        fn into_par_iter(self) -> Self::Iter {
            self.into_iter()
        }
    }
}

#[cfg(not(all(target_family = "wasm", target_os = "unknown")))]
mod turns;
#[cfg(not(all(target_family = "wasm", target_os = "unknown")))]
pub use turns::{Policy, Remaining, Turn, longest_first, longest_first_on, takes_over};

/// A job's turn (no threads: every job runs alone, and [`Turn::tick`] never waits).
#[cfg(all(target_family = "wasm", target_os = "unknown"))]
#[derive(Debug, Default)]
pub struct Turn<'a> {
    _jobs: std::marker::PhantomData<&'a ()>,
}

#[cfg(all(target_family = "wasm", target_os = "unknown"))]
impl Turn<'_> {
    /// A turn that never waits.
    pub fn alone() -> Turn<'static> {
        Turn::default()
    }

    /// Does nothing: no other job waits for the core.
    pub fn tick(&self, _done: f64) {}
}

/// `f` of every item, in order (no threads).
#[cfg(all(target_family = "wasm", target_os = "unknown"))]
pub fn longest_first<T, R>(items: &[T], f: impl Fn(&T, &Turn) -> R) -> Vec<R> {
    let turn = Turn::alone();
    items.iter().map(|x| f(x, &turn)).collect()
}
