//! Running jobs on N threads while reporting results in job order: each result is handed to
//! the caller as soon as it and every earlier one are done, so the printed order is stable
//! whatever the timing. A job that panics yields the panic message instead of a result.

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc;

/// The text of a panic payload.
fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = payload.downcast_ref::<&str>() {
        (*s).to_string()
    } else if let Some(s) = payload.downcast_ref::<String>() {
        s.clone()
    } else {
        "unknown panic".to_string()
    }
}

/// The threads of a command's `--jobs N`: N, or every core of the machine.
pub fn threads(jobs: Option<u32>) -> usize {
    jobs.map_or_else(
        || std::thread::available_parallelism().map_or(1, |n| n.get()),
        |j| j as usize,
    )
}

/// Runs `work` on every item with up to `jobs` threads; calls `done(index, result)` in index
/// order on the calling thread.
pub fn run_in_order<T: Sync, R: Send>(
    items: &[T],
    jobs: usize,
    work: impl Fn(&T) -> R + Sync,
    mut done: impl FnMut(usize, Result<R, String>),
) {
    let next = AtomicUsize::new(0);
    let (send, receive) = mpsc::channel::<(usize, Result<R, String>)>();
    std::thread::scope(|scope| {
        for _ in 0..jobs.clamp(1, items.len().max(1)) {
            let (next, work) = (&next, &work);
            // `depth`: the call depth the worker's stack holds.
            let worker = |send: mpsc::Sender<_>, depth: usize| {
                move || {
                    crate::kernel::set_call_depth_limit(depth);
                    loop {
                        let k = next.fetch_add(1, Ordering::Relaxed);
                        let Some(item) = items.get(k) else { break };
                        let result = catch_unwind(AssertUnwindSafe(|| work(item)))
                            .map_err(|p| panic_message(p.as_ref()));
                        if send.send((k, result)).is_err() {
                            break; // The receiver is gone: nobody wants more results.
                        }
                    }
                }
            };
            // Each testbench allows ordinary recursion, as `vams run` does; a machine without
            // the address space for the deep stack gets an ordinary thread and depth.
            let deep = std::thread::Builder::new().stack_size(crate::kernel::DEEP_STACK);
            let deep_worker = worker(send.clone(), crate::kernel::DEEP_CALL_DEPTH);
            if deep.spawn_scoped(scope, deep_worker).is_err() {
                scope.spawn(worker(send.clone(), crate::kernel::DEFAULT_CALL_DEPTH));
            }
        }
        drop(send);
        let mut pending: Vec<Option<Result<R, String>>> = (0..items.len()).map(|_| None).collect();
        let mut printed = 0;
        for (k, result) in receive {
            pending[k] = Some(result);
            while let Some(ready) = pending.get_mut(printed).and_then(Option::take) {
                done(printed, ready);
                printed += 1;
            }
        }
    });
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::{Duration, Instant};

    #[test]
    fn results_arrive_in_order_whatever_the_timing() {
        // Later items finish first.
        let items: Vec<u64> = (0..8).collect();
        let mut seen = Vec::new();
        run_in_order(
            &items,
            4,
            |&k| {
                std::thread::sleep(Duration::from_millis(5 * (8 - k)));
                k * k
            },
            |k, r| seen.push((k, r.unwrap())),
        );
        let want: Vec<(usize, u64)> = (0..8).map(|k| (k as usize, k * k)).collect();
        assert_eq!(seen, want);
    }

    #[test]
    fn jobs_run_in_parallel() {
        let items = [(); 4];
        let start = Instant::now();
        run_in_order(
            &items,
            4,
            |_| std::thread::sleep(Duration::from_millis(200)),
            |_, _| {},
        );
        // Serially this takes 800 ms; four threads take about 200 ms.
        assert!(
            start.elapsed() < Duration::from_millis(700),
            "{:?}",
            start.elapsed()
        );
    }

    #[test]
    fn a_panicking_job_reports_its_message_and_the_others_complete() {
        let items = [1, 2, 3];
        let mut seen = Vec::new();
        run_in_order(
            &items,
            2,
            |&k| {
                if k == 2 {
                    panic!("job two broke");
                }
                k
            },
            |k, r| seen.push((k, r)),
        );
        assert_eq!(seen.len(), 3);
        assert_eq!(seen[0].1, Ok(1));
        assert_eq!(seen[1].1, Err("job two broke".to_string()));
        assert_eq!(seen[2].1, Ok(3));
    }

    #[test]
    fn no_items_no_calls() {
        let items: [u8; 0] = [];
        run_in_order(&items, 3, |_| (), |_, _| panic!("no results expected"));
    }
}
