//! A background thread for slow computations. The newest request wins: a new
//! job cancels the running one, and results of older jobs are dropped. The
//! window keeps drawing the last good result meanwhile.

use crate::scene::{Progress, SceneError};
use std::sync::mpsc::{Receiver, Sender, channel};
use std::thread;

type Task<T> = Box<dyn FnOnce(&Progress) -> Result<T, SceneError> + Send>;

struct Job<T> {
    generation: u64,
    progress: Progress,
    task: Task<T>,
}

/// A worker thread computing results of type `T`.
pub struct Worker<T: Send + 'static> {
    jobs: Sender<Job<T>>,
    done: Receiver<(u64, Result<T, SceneError>)>,
    generation: u64,
    running: Option<Progress>,
}

impl<T: Send + 'static> Worker<T> {
    /// Starts the thread; `repaint` is called whenever a result is ready.
    pub fn new(repaint: impl Fn() + Send + 'static) -> Self {
        let (jobs, job_rx) = channel::<Job<T>>();
        let (done_tx, done) = channel();
        thread::Builder::new()
            .name("grainscope-worker".into())
            .spawn(move || {
                while let Ok(mut job) = job_rx.recv() {
                    // Skip to the newest queued job.
                    while let Ok(newer) = job_rx.try_recv() {
                        job = newer;
                    }
                    let result = (job.task)(&job.progress);
                    if done_tx.send((job.generation, result)).is_err() {
                        break;
                    }
                    repaint();
                }
            })
            .ok();
        Worker { jobs, done, generation: 0, running: None }
    }

    /// Queues a job, cancelling the one that is running.
    pub fn submit(&mut self, task: impl FnOnce(&Progress) -> Result<T, SceneError> + Send + 'static) {
        self.cancel();
        self.generation += 1;
        let progress = Progress::default();
        self.running = Some(progress.clone());
        // A closed channel means the thread is gone; the job is then dropped
        // and `busy` stays true, which the window shows.
        let _ = self.jobs.send(Job { generation: self.generation, progress, task: Box::new(task) });
    }

    /// Cancels the running job, if any.
    pub fn cancel(&mut self) {
        if let Some(p) = self.running.take() {
            p.cancel();
        }
    }

    /// Whether a job is running.
    pub fn busy(&self) -> bool {
        self.running.is_some()
    }

    /// The newest intermediate result the running job offered.
    pub fn partial(&self) -> Option<std::sync::Arc<crate::scene::SceneOutput>> {
        self.running.as_ref().and_then(Progress::partial)
    }

    /// Pauses or resumes the running job (jobs that do not honour pauses run on).
    pub fn set_paused(&self, paused: bool) {
        if let Some(p) = &self.running {
            p.set_paused(paused);
        }
    }

    /// Whether the running job is paused.
    pub fn paused(&self) -> bool {
        self.running.as_ref().is_some_and(Progress::paused)
    }

    /// Fraction done of the running job.
    pub fn progress(&self) -> f64 {
        self.running.as_ref().map_or(0.0, Progress::fraction)
    }

    /// The result of the newest job, once it is ready; results of older jobs
    /// and of cancelled ones are dropped.
    pub fn poll(&mut self) -> Option<Result<T, SceneError>> {
        let mut latest = None;
        while let Ok((generation, result)) = self.done.try_recv() {
            if generation == self.generation && !matches!(result, Err(SceneError::Cancelled)) {
                latest = Some(result);
            }
            if generation == self.generation {
                self.running = None;
            }
        }
        latest
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::{Duration, Instant};

    #[test]
    fn newest_job_wins_and_old_results_are_dropped() {
        let mut w: Worker<u32> = Worker::new(|| {});
        w.submit(|p| {
            for _ in 0..200 {
                p.check()?;
                thread::sleep(Duration::from_millis(1));
            }
            Ok(1)
        });
        w.submit(|_| Ok(2));
        let start = Instant::now();
        let mut got = None;
        while got.is_none() && start.elapsed() < Duration::from_secs(10) {
            got = w.poll();
            thread::sleep(Duration::from_millis(1));
        }
        assert_eq!(got.map(|r| r.ok()), Some(Some(2)));
        assert!(!w.busy());
    }
}
