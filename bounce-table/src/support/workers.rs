//! Work spread over threads, which falls back to the calling thread when the system refuses a
//! thread (a memory or process limit): the answer is the same, only slower. `std`'s
//! `Scope::spawn` panics there instead.

use std::thread::{Scope, ScopedJoinHandle};

/// One piece of work: running on a thread of its own, or refused a thread and waiting to run
/// on the caller's.
pub enum Job<'scope, T> {
    /// On its own thread.
    Running(ScopedJoinHandle<'scope, T>),
    /// No thread was given: [`Job::join`] runs it.
    Refused(usize),
}

impl<T> Job<'_, T> {
    /// True once the work is done (a refused job has not started).
    #[must_use]
    pub fn is_finished(&self) -> bool {
        match self {
            Self::Running(h) => h.is_finished(),
            Self::Refused(_) => true,
        }
    }

    /// The result: the thread's, or `work(k)` run here for a refused job; `None` if the
    /// worker panicked.
    pub fn join(self, work: &(impl Fn(usize) -> T + Sync)) -> Option<T> {
        match self {
            Self::Running(h) => h.join().ok(),
            Self::Refused(k) => Some(work(k)),
        }
    }
}

/// Starts `work(k)` for every k in 0..n, each on a thread of its own where the system gives
/// one.
pub fn spawn_each<'scope, 'env, T, W>(
    scope: &'scope Scope<'scope, 'env>,
    n: usize,
    work: &'env W,
) -> Vec<Job<'scope, T>>
where
    T: Send + 'scope,
    W: Fn(usize) -> T + Sync,
{
    (0..n)
        .map(|k| {
            std::thread::Builder::new()
                .spawn_scoped(scope, move || work(k))
                .map_or(Job::Refused(k), Job::Running)
        })
        .collect()
}

/// `work(k)` for every k in 0..n, in parallel where the system allows; results in order of k,
/// `None` where a worker panicked.
pub fn each<T: Send, W: Fn(usize) -> T + Sync>(n: usize, work: &W) -> Vec<Option<T>> {
    std::thread::scope(|scope| {
        spawn_each(scope, n, work)
            .into_iter()
            .map(|job| job.join(work))
            .collect()
    })
}

/// `work(k)` for every k in 0..n on threads of their own (as [`spawn_each`]) while `meanwhile`
/// runs on the calling thread: the results in order of k (a worker that panicked, or a thread
/// refused, has its share run here), and `meanwhile`'s. A pipeline's step: this block worked
/// on while the last one is stored and the next one read.
pub fn each_while<T: Send, M, W: Fn(usize) -> T + Sync>(
    n: usize,
    work: &W,
    meanwhile: impl FnOnce() -> M,
) -> (Vec<T>, M) {
    std::thread::scope(|scope| {
        let jobs = spawn_each(scope, n, work);
        let beside = meanwhile();
        let results = jobs
            .into_iter()
            .enumerate()
            .map(|(k, job)| job.join(work).unwrap_or_else(|| work(k)))
            .collect();
        (results, beside)
    })
}
