//! A computation shared among processes that share no memory (a browser's
//! Web Workers). A heavy scene maps its independent units (the disks of a
//! grid, the runs of a column) through [`Progress::units`]. Where no
//! [`Parts`] is given, that is a parallel map on this process's threads.
//! Where one is, each process computes the same scene up to the first map
//! whose units are not all known, computes its share of the unknown ones
//! there and stops; whoever started the processes gathers every share into
//! [`Parts::known`] and starts the computation again, until it runs through.
//! The units are numbered in the order the maps ask for them, which depends
//! on the parameters alone, and each value travels as its shortest exact
//! text, so the result is the same to the last bit however many processes
//! share it.

use super::core::{Progress, SceneError};
use crate::parallel::Turn;
use crate::parallel::prelude::*;
use serde::Serialize;
use serde::de::DeserializeOwned;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Which share of a computation's units this process computes, and the
/// values of units other processes have computed.
#[derive(Debug, Clone, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Parts {
    /// This process's share, from 0.
    pub part: usize,
    /// How many processes share the units.
    pub of: usize,
    /// Values already known: (unit number, value as RON text).
    pub known: Vec<(usize, String)>,
}

/// What a process computing with [`Parts`] did: the units it was given and
/// whether it stopped at a map it shared with others.
#[derive(Debug, Default)]
pub(super) struct Ledger {
    plan: Parts,
    /// The next unit number.
    next: AtomicUsize,
    /// Units computed here: (unit number, value as RON text).
    made: Mutex<Vec<(usize, String)>>,
    /// How many processes the map it stopped at was shared among (0 while
    /// it has stopped at none).
    shared_among: AtomicUsize,
    /// Whether one of its own units is computing: maps inside a unit are
    /// that unit's own (other processes never see them), so they are not
    /// shared.
    inside: std::sync::atomic::AtomicBool,
}

impl Ledger {
    pub(super) fn new(plan: Parts) -> Self {
        Ledger { plan, ..Ledger::default() }
    }

    fn known<R: DeserializeOwned>(&self, unit: usize) -> Option<R> {
        let (_, text) = self.plan.known.iter().find(|(u, _)| *u == unit)?;
        // As the page's messages are read (one reader compiled for both).
        ron::de::from_bytes(text.as_bytes()).ok()
    }
}

/// Where a computation with [`Parts`] stopped: the map it shared, and the
/// values of the units this process computed there.
#[derive(Debug, Clone, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Share {
    /// How many processes share that map's unknown units (each takes every
    /// `of`-th, from its part on).
    pub of: usize,
    /// (unit number, value as RON text).
    pub made: Vec<(usize, String)>,
}

impl Progress {
    /// A progress whose computation takes its share of `parts`.
    pub fn with_parts(mut self, parts: Parts) -> Progress {
        self.parts = Some(std::sync::Arc::new(Ledger::new(parts)));
        self
    }

    /// How many processes share this computation's maps (1 where none do).
    /// Each reports the units it computed out of all, and whoever started
    /// them adds the reports up: a unit done in an earlier round counts
    /// 1/`sharers` in each.
    pub fn sharers(&self) -> usize {
        self.parts.as_ref().map_or(1, |l| l.plan.of.max(1))
    }

    /// Where the computation stopped to share a map with other processes
    /// (`None` if it did not: it ran through, or has no [`Parts`]).
    pub fn share(&self) -> Option<Share> {
        let ledger = self.parts.as_ref()?;
        let of = ledger.shared_among.load(Ordering::Relaxed);
        if of == 0 {
            return None;
        }
        let made = ledger.made.lock().map(|m| m.clone()).unwrap_or_default();
        Some(Share { of, made })
    }

    /// `f` of every item, in order: the independent units of a heavy
    /// computation (see the module's text). Without [`Parts`], in parallel
    /// on this process's threads. With them, known units are read back; if
    /// some are unknown, this process computes its share of those and the
    /// computation stops here with [`SceneError::Cancelled`] ([`Progress::share`]
    /// then says what it made).
    pub fn units<T, R, F>(&self, items: &[T], f: F) -> Result<Vec<R>, SceneError>
    where
        T: Sync,
        R: Send + Serialize + DeserializeOwned,
        F: Fn(&T) -> Result<R, SceneError> + Sync + Send,
    {
        self.units_mapped(items, &|x, _| f(x), |xs, g| xs.par_iter().map(|x| g(x, &Turn::alone())).collect())
    }

    /// As [`Progress::units`], for long sequential units (Monte Carlo runs):
    /// without [`Parts`], each on a thread of its own, taking turns on this
    /// process's cores ([`crate::parallel::longest_first`]: each unit reports its
    /// fraction done to its [`Turn`]).
    pub fn units_longest_first<T, R, F>(&self, items: &[T], f: F) -> Result<Vec<R>, SceneError>
    where
        T: Sync,
        R: Send + Serialize + DeserializeOwned,
        F: Fn(&T, &Turn) -> Result<R, SceneError> + Sync + Send,
    {
        self.units_mapped(items, &f, |xs, g| crate::parallel::longest_first(xs, g).into_iter().collect())
    }

    /// The units of `items` through `f`: where no process shares them, all
    /// of them through `plain`.
    fn units_mapped<T, R>(
        &self,
        items: &[T],
        f: &(dyn Fn(&T, &Turn) -> Result<R, SceneError> + Sync),
        plain: impl FnOnce(&[T], &(dyn Fn(&T, &Turn) -> Result<R, SceneError> + Sync)) -> Result<Vec<R>, SceneError>,
    ) -> Result<Vec<R>, SceneError>
    where
        T: Sync,
        R: Send + Serialize + DeserializeOwned,
    {
        let Some(ledger) = self.parts.as_ref().filter(|l| !l.inside.load(Ordering::Relaxed)) else {
            return plain(items, f);
        };
        let first = ledger.next.fetch_add(items.len(), Ordering::Relaxed);
        let mut values: Vec<Option<R>> = (0..items.len()).map(|i| ledger.known(first + i)).collect();
        let unknown: Vec<usize> = (0..items.len()).filter(|&i| values[i].is_none()).collect();
        if unknown.is_empty() {
            return Ok(values.into_iter().flatten().collect());
        }
        let of = ledger.plan.of.clamp(1, unknown.len());
        let part = ledger.plan.part;
        if of > 1 {
            self.tell(super::core::Report::Sharing(of));
        }
        for (_, &i) in unknown.iter().enumerate().filter(|(j, _)| j % of == part) {
            ledger.inside.store(true, Ordering::Relaxed);
            let value = f(&items[i], &Turn::alone());
            ledger.inside.store(false, Ordering::Relaxed);
            let value = value?;
            let text = ron::to_string(&value).map_err(|e| {
                SceneError::Physics(crate::physics::PhysicsError::Invalid(format!(
                    "a unit's value cannot be shared: {e}"
                )))
            })?;
            values[i] = Some(value);
            if let Ok(mut made) = ledger.made.lock() {
                made.push((first + i, text));
            }
        }
        if of == 1 {
            // This process was the only one to share them: it ran them all.
            return Ok(values.into_iter().flatten().collect());
        }
        ledger.shared_among.store(of, Ordering::Relaxed);
        Err(SceneError::Cancelled)
    }
}

/// `compute` shared among `n` processes as a browser shares it among its
/// workers, with the processes taking turns here: round by round, part 0
/// runs until it stops at a shared map, parts 1.. of that map follow, and
/// their values go into the next round's known units. The rounds it took
/// come with the result. (What the page does with its workers, for tests
/// and comparisons on one machine.)
pub fn in_turns<T>(n: usize, compute: impl Fn(&Progress) -> Result<T, SceneError>) -> Result<(T, usize), SceneError> {
    let mut known = Vec::new();
    for round in 1.. {
        let first = Progress::default().with_parts(Parts { part: 0, of: n, known: known.clone() });
        let result = compute(&first);
        let Some(share) = first.share() else { return result.map(|r| (r, round)) };
        let mut made = share.made;
        for part in 1..share.of {
            let p = Progress::default().with_parts(Parts { part, of: n, known: known.clone() });
            // Every part stops at the same map, with its share made.
            let _ = compute(&p);
            made.extend(p.share().map(|s| s.made).unwrap_or_default());
        }
        if made.is_empty() {
            return Err(SceneError::Cancelled);
        }
        known.extend(made);
    }
    unreachable!("rounds are unbounded")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A computation of two maps, the second built on the first.
    fn two_maps(progress: &Progress, calls: &AtomicUsize) -> Result<Vec<f64>, SceneError> {
        let xs: Vec<f64> = (0..7).map(|i| 0.1 + i as f64).collect();
        let squares = progress.units(&xs, |x| {
            calls.fetch_add(1, Ordering::Relaxed);
            Ok(x * x / 3.0)
        })?;
        progress.units(&squares, |s| {
            calls.fetch_add(1, Ordering::Relaxed);
            Ok(s.sqrt().exp())
        })
    }

    /// Shared among 1, 2, 3 or 10 processes round by round, the result is
    /// the undivided one to the bit, and every unit runs exactly once.
    #[test]
    fn shared_computations_equal_the_undivided_one() {
        let calls = AtomicUsize::new(0);
        let whole = two_maps(&Progress::default(), &calls).expect("runs");
        assert_eq!(calls.load(Ordering::Relaxed), 14);
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        for n in [1, 2, 3, 10] {
            let calls = AtomicUsize::new(0);
            let (shared, rounds) = in_turns(n, |p| two_maps(p, &calls)).expect("runs");
            assert_eq!(bits(&shared), bits(&whole), "{n} processes");
            assert_eq!(calls.load(Ordering::Relaxed), 14, "{n} processes: each unit once");
            assert_eq!(rounds, if n == 1 { 1 } else { 3 }, "{n} processes");
        }
    }

    /// Maps inside a unit belong to it: shared among 2 processes, a map of
    /// maps numbers only its outer units, and equals the undivided one.
    #[test]
    fn maps_inside_a_unit_are_not_shared() {
        let nested = |p: &Progress| {
            p.units(&[1.0, 2.0, 3.0], |x: &f64| {
                let inner = p.units(&[*x, x + 0.5], |y: &f64| Ok(y.ln()))?;
                Ok(inner.iter().sum::<f64>())
            })
        };
        let whole = nested(&Progress::default()).expect("runs");
        let (shared, rounds) = in_turns(2, nested).expect("runs");
        assert_eq!(shared, whole);
        assert_eq!(rounds, 2);
    }

    /// A map of fewer units than processes is shared among as many as it has.
    #[test]
    fn a_map_is_shared_among_no_more_processes_than_units() {
        let p = Progress::default().with_parts(Parts { part: 0, of: 8, known: Vec::new() });
        let out = p.units(&[1.0, 2.0, 3.0], |x: &f64| Ok(2.0 * x));
        assert!(matches!(out, Err(SceneError::Cancelled)));
        let share = p.share().expect("stopped");
        assert_eq!(share.of, 3);
        assert_eq!(share.made, vec![(0, "2.0".to_string())]);
        // A part beyond the units makes nothing.
        let q = Progress::default().with_parts(Parts { part: 5, of: 8, known: Vec::new() });
        assert!(q.units(&[1.0, 2.0, 3.0], |x: &f64| Ok(2.0 * x)).is_err());
        assert_eq!(q.share().map(|s| s.made.len()), Some(0));
        // Without parts, no share.
        assert_eq!(Progress::default().share(), None);
    }
}
