//! Work side by side: a few threads take items off one list, and the
//! caller hears of each result, on its own thread, as it comes.

use std::sync::Mutex;
use std::sync::mpsc;

/// Runs `work` on every item, `jobs` at a time, and hands each result to
/// `done` (on the calling thread, in the order they finish).
pub fn for_each<T, R>(
    items: Vec<T>,
    jobs: usize,
    work: impl Fn(T) -> R + Sync,
    mut done: impl FnMut(R),
) where
    T: Send,
    R: Send,
{
    let count = items.len();
    let queue = Mutex::new(items.into_iter());
    let (tx, rx) = mpsc::channel();
    std::thread::scope(|scope| {
        for _ in 0..jobs.clamp(1, count.max(1)) {
            let (tx, queue, work) = (tx.clone(), &queue, &work);
            scope.spawn(move || {
                loop {
                    let next = queue.lock().map(|mut q| q.next()).unwrap_or(None);
                    let Some(item) = next else { break };
                    if tx.send(work(item)).is_err() {
                        break;
                    }
                }
            });
        }
        drop(tx);
        for result in rx {
            done(result);
        }
    });
}

#[cfg(test)]
mod tests {
    #[test]
    fn every_item_is_done_once() {
        let mut seen = Vec::new();
        super::for_each((0..20).collect(), 3, |i| i * 2, |r| seen.push(r));
        seen.sort();
        assert_eq!(seen, (0..20).map(|i| i * 2).collect::<Vec<_>>());
    }
}
