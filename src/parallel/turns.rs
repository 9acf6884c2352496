//! Long sequential jobs taking turns on the cores. Where a computation has
//! more independent jobs than cores (three Monte Carlo columns on two
//! cores), running whole jobs one after another leaves a core idle at the
//! end: three columns of 13.3, 17.0 and 7.2 s of CPU take 20.5 s, where
//! 18.75 s (their sum over two cores) is possible if a job can be paused
//! and resumed. [`longest_first`] gives every job a thread of its own and lets
//! at most as many as there are cores run at once; each job reports the
//! fraction it has done ([`Turn::tick`]), and a running job hands its core
//! to a waiting one whose estimated remaining time is longer than its own
//! (longest remaining time first, which is the shortest schedule on
//! identical cores). The estimate is the remaining fraction over the rate
//! of the last second of the job's own running time; a job is unknown,
//! and first in line, until it has run two seconds. What a job computes
//! does not depend on when it runs, so the results are those of a plain
//! map to the last bit.

use std::sync::{Condvar, Mutex, MutexGuard};
use std::time::{Duration, Instant};

/// How jobs take turns: the span of running time over which a job's rate
/// is measured (its estimate is unknown until it has run twice this: the
/// first fraction of a Monte Carlo run, in log time, goes much faster than
/// the rest), and the running time a job keeps its core at least before it
/// compares itself with the waiting ones.
#[derive(Debug, Clone, Copy)]
pub struct Policy {
    /// Span of running time for the rate, in s.
    pub window: f64,
    /// Least time on a core before a hand-over.
    pub quantum: Duration,
}

impl Default for Policy {
    /// A second's window and half a second's turns: a hand-over (a thread
    /// woken, its data back into the cache) costs well under a millisecond.
    fn default() -> Self {
        Policy { window: 1.0, quantum: Duration::from_millis(500) }
    }
}
/// A waiting job takes a running one's core when its remaining time is
/// longer by this factor and [`MARGIN`] seconds.
const RATIO: f64 = 1.15;
/// See [`RATIO`].
const MARGIN: f64 = 0.05;

/// The remaining running time of a job from its fraction done against its
/// own running time: (1 − done)/rate, the rate over the last window of
/// running time. Infinite (first in line) until it has run two windows, or
/// while it makes no progress.
#[derive(Debug, Clone)]
pub struct Remaining {
    window: f64,
    /// (running time in s, fraction done), one sample per tenth of the window.
    samples: Vec<(f64, f64)>,
}

impl Remaining {
    /// No samples yet, with a rate measured over `window` seconds.
    pub fn new(window: f64) -> Self {
        Remaining { window, samples: Vec::new() }
    }

    /// Records the fraction `done` at `run_time` seconds of the job's running time.
    pub fn record(&mut self, run_time: f64, done: f64) {
        // Samples a tenth of the window apart or more, the newest replaced
        // until the next is due.
        let n = self.samples.len();
        if n >= 2 && self.samples[n - 1].0 - self.samples[n - 2].0 < 0.1 * self.window {
            self.samples[n - 1] = (run_time, done);
        } else {
            self.samples.push((run_time, done));
        }
        // Keep what the window needs.
        let keep_from = self.samples.iter().rposition(|&(t, _)| run_time - t >= self.window).unwrap_or(0);
        if keep_from > 0 {
            self.samples.drain(..keep_from);
        }
    }

    /// The estimated remaining running time in seconds (infinite while unknown).
    pub fn seconds(&self) -> f64 {
        let (Some(&(t0, f0)), Some(&(t1, f1))) = (self.samples.first(), self.samples.last()) else {
            return f64::INFINITY;
        };
        if t1 < 2.0 * self.window || t1 - t0 < 0.5 * self.window || f1 <= f0 {
            return f64::INFINITY;
        }
        (1.0 - f1).max(0.0) * (t1 - t0) / (f1 - f0)
    }
}

/// Whether a waiting job with `waiting` seconds left should take the core
/// of a running one with `running` left.
pub fn takes_over(waiting: f64, running: f64) -> bool {
    running.is_finite() && waiting > RATIO * running + MARGIN
}

/// The jobs' shared state: who runs, who waits, and each one's estimate.
#[derive(Debug)]
struct Board {
    free: usize,
    waiting: Vec<bool>,
    estimate: Vec<f64>,
}

impl Board {
    /// The waiting job first in line: the longest estimate, then the lowest number.
    fn first_waiting(&self) -> Option<usize> {
        let mut best: Option<usize> = None;
        for (j, _) in self.waiting.iter().enumerate().filter(|(_, w)| **w) {
            if best.is_none_or(|b| self.estimate[j] > self.estimate[b]) {
                best = Some(j);
            }
        }
        best
    }
}

/// The cores shared among the jobs of one [`longest_first`].
#[derive(Debug)]
struct Gate {
    policy: Policy,
    board: Mutex<Board>,
    changed: Condvar,
}

impl Gate {
    fn lock(&self) -> MutexGuard<'_, Board> {
        self.board.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Waits until job `id` is first in line and a core is free, and takes it.
    fn take(&self, mut board: MutexGuard<'_, Board>, id: usize) {
        board.waiting[id] = true;
        while !(board.free > 0 && board.first_waiting() == Some(id)) {
            board = self.changed.wait(board).unwrap_or_else(|e| e.into_inner());
        }
        board.waiting[id] = false;
        board.free -= 1;
        // Another core may be free for the next in line.
        self.changed.notify_all();
    }

    fn give_back(&self, mut board: MutexGuard<'_, Board>) {
        board.free += 1;
        self.changed.notify_all();
    }
}

/// A job's running time and estimate.
#[derive(Debug)]
struct Clock {
    /// When the current turn began.
    since: Instant,
    /// Running time before the current turn, in s.
    before: f64,
    remaining: Remaining,
}

impl Clock {
    fn new(window: f64) -> Self {
        Clock { since: Instant::now(), before: 0.0, remaining: Remaining::new(window) }
    }
}

/// A job's turn on the cores, handed to it by [`longest_first`]: the job calls
/// [`Turn::tick`] now and then.
#[derive(Debug)]
pub struct Turn<'a> {
    gate: Option<(&'a Gate, usize)>,
    clock: Mutex<Clock>,
}

impl Turn<'_> {
    /// A turn that never waits (a job that shares its core with none).
    pub fn alone() -> Turn<'static> {
        Turn { gate: None, clock: Mutex::new(Clock::new(1.0)) }
    }

    /// Reports the fraction of the job done; may wait here while other jobs
    /// take the core (cheap when it does not: a clock read).
    pub fn tick(&self, done: f64) {
        let Some((gate, id)) = self.gate else { return };
        let Ok(mut clock) = self.clock.lock() else { return };
        let in_turn = clock.since.elapsed();
        let run_time = clock.before + in_turn.as_secs_f64();
        clock.remaining.record(run_time, done);
        if in_turn < gate.policy.quantum {
            return;
        }
        let mine = clock.remaining.seconds();
        let mut board = gate.lock();
        board.estimate[id] = mine;
        let Some(next) = board.first_waiting() else { return };
        if !takes_over(board.estimate[next], mine) {
            return;
        }
        clock.before = run_time;
        gate.give_back(board);
        gate.take(gate.lock(), id);
        clock.since = Instant::now();
    }
}

/// `f` of every item, in order, each item a job on a thread of its own,
/// at most `cores` running at once and taking turns as the module's text
/// says. With no more items than `cores`, a plain parallel map.
pub fn longest_first_on<T: Sync, R: Send>(
    cores: usize,
    policy: Policy,
    items: &[T],
    f: impl Fn(&T, &Turn) -> R + Sync,
) -> Vec<R> {
    use rayon::prelude::*;
    let cores = cores.max(1);
    if items.len() <= cores {
        return items.par_iter().map(|x| f(x, &Turn::alone())).collect();
    }
    let gate = Gate {
        policy,
        board: Mutex::new(Board {
            free: cores,
            waiting: vec![false; items.len()],
            estimate: vec![f64::INFINITY; items.len()],
        }),
        changed: Condvar::new(),
    };
    let (gate, f) = (&gate, &f);
    std::thread::scope(|s| {
        let handles: Vec<_> = items
            .iter()
            .enumerate()
            .map(|(id, item)| {
                s.spawn(move || {
                    gate.take(gate.lock(), id);
                    let turn = Turn { gate: Some((gate, id)), clock: Mutex::new(Clock::new(gate.policy.window)) };
                    // Gives the core back however the job ends.
                    struct Done<'g>(&'g Gate, usize);
                    impl Drop for Done<'_> {
                        fn drop(&mut self) {
                            let mut board = self.0.lock();
                            board.estimate[self.1] = 0.0;
                            self.0.give_back(board);
                        }
                    }
                    let _done = Done(gate, id);
                    f(item, &turn)
                })
            })
            .collect();
        handles.into_iter().map(|h| h.join().unwrap_or_else(|e| std::panic::resume_unwind(e))).collect()
    })
}

/// [`longest_first_on`] this process's cores (the thread pool's size). Called
/// on a worker of the thread pool (inside a parallel map: the points of a
/// sweep), a plain parallel map: the pool already keeps every core busy,
/// and threads of their own would crowd it.
pub fn longest_first<T: Sync, R: Send>(items: &[T], f: impl Fn(&T, &Turn) -> R + Sync) -> Vec<R> {
    let cores = if rayon::current_thread_index().is_some() { items.len() } else { rayon::current_num_threads() };
    longest_first_on(cores, Policy::default(), items, f)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicUsize, Ordering};

    /// Progress linear in running time gives the exact remaining time once
    /// known; a fast start outside the window does not count.
    #[test]
    fn remaining_time_of_steady_progress() {
        let mut r = Remaining::new(1.0);
        // Half done in the first 0.2 s, then 0.05 a second.
        r.record(0.0, 0.0);
        r.record(0.2, 0.5);
        assert_eq!(r.seconds(), f64::INFINITY);
        for k in 3..=25 {
            let t = 0.1 * k as f64;
            r.record(t, 0.5 + 0.05 * (t - 0.2));
        }
        let left = 1.0 - (0.5 + 0.05 * 2.3);
        assert!((r.seconds() - left / 0.05).abs() < 1e-9, "{} against {}", r.seconds(), left / 0.05);
        // No progress: unknown again.
        let mut stuck = Remaining::new(1.0);
        for k in 0..40 {
            stuck.record(0.1 * k as f64, 0.3);
        }
        assert_eq!(stuck.seconds(), f64::INFINITY);
    }

    /// Unknown jobs go first; known ones take over only when clearly longer.
    #[test]
    fn longest_remaining_takes_over() {
        assert!(takes_over(f64::INFINITY, 3.0));
        assert!(!takes_over(f64::INFINITY, f64::INFINITY));
        assert!(!takes_over(3.3, 3.0));
        assert!(takes_over(3.6, 3.0));
        assert!(!takes_over(1.0, 3.0));
    }

    /// Five jobs on two cores: the results in order, as a plain map's, and
    /// never more than two running at once, however they take turns.
    #[test]
    fn jobs_take_turns_on_the_cores() {
        let running = AtomicUsize::new(0);
        let most = AtomicUsize::new(0);
        let items: Vec<u64> = (1..=5).collect();
        let out = longest_first_on(2, Policy::default(), &items, |&n, turn| {
            let now = running.fetch_add(1, Ordering::SeqCst) + 1;
            most.fetch_max(now, Ordering::SeqCst);
            let mut x = n;
            for step in 0..200u64 {
                x = x.wrapping_mul(6364136223846793005).wrapping_add(step);
                running.fetch_sub(1, Ordering::SeqCst);
                turn.tick(step as f64 / 200.0);
                let now = running.fetch_add(1, Ordering::SeqCst) + 1;
                most.fetch_max(now, Ordering::SeqCst);
                std::thread::sleep(Duration::from_millis(1 + n % 3));
            }
            running.fetch_sub(1, Ordering::SeqCst);
            x
        });
        let plain: Vec<u64> = items
            .iter()
            .map(|&n| {
                let mut x = n;
                for step in 0..200u64 {
                    x = x.wrapping_mul(6364136223846793005).wrapping_add(step);
                }
                x
            })
            .collect();
        assert_eq!(out, plain);
        assert_eq!(most.load(Ordering::SeqCst), 2, "at most two at once, and two at some time");
    }

    /// Three jobs on two cores with short turns: the third starts before
    /// either of the first two ends (a whole-job schedule would start it
    /// only then), and all end with their results.
    #[test]
    fn a_waiting_job_takes_a_core_before_one_is_free() {
        let policy = Policy { window: 0.02, quantum: Duration::from_millis(5) };
        let ended = AtomicUsize::new(0);
        let started_before_an_end = AtomicUsize::new(0);
        let out = longest_first_on(2, policy, &[0usize, 1, 2], |&n, turn| {
            if ended.load(Ordering::SeqCst) == 0 {
                started_before_an_end.fetch_add(1, Ordering::SeqCst);
            }
            for step in 0..300 {
                turn.tick(step as f64 / 300.0);
                std::thread::sleep(Duration::from_millis(1));
            }
            ended.fetch_add(1, Ordering::SeqCst);
            n * 10
        });
        assert_eq!(out, vec![0, 10, 20]);
        assert_eq!(started_before_an_end.load(Ordering::SeqCst), 3);
    }
}
