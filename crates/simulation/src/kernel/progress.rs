//! The progress hook: a caller's callback told the simulated time as a run advances, at most
//! once per interval of wall time so that a fast run pays one clock read per step and nothing
//! more. The kernel never prints; the callback decides what progress looks like.

use std::fmt;
use std::sync::Arc;
use std::time::{Duration, Instant};

/// Called with the simulated time (seconds) at most once per `interval` of wall time.
#[derive(Clone)]
pub struct ProgressHook {
    callback: Arc<dyn Fn(f64) + Send + Sync>,
    interval: Duration,
}

impl ProgressHook {
    /// The default interval between calls.
    pub const INTERVAL: Duration = Duration::from_millis(50);

    /// A hook called at most every [`ProgressHook::INTERVAL`].
    pub fn new(callback: impl Fn(f64) + Send + Sync + 'static) -> ProgressHook {
        ProgressHook::every(ProgressHook::INTERVAL, callback)
    }

    /// A hook called at most once per `interval`.
    pub fn every(
        interval: Duration,
        callback: impl Fn(f64) + Send + Sync + 'static,
    ) -> ProgressHook {
        ProgressHook {
            callback: Arc::new(callback),
            interval,
        }
    }
}

impl fmt::Debug for ProgressHook {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("ProgressHook")
            .field("interval", &self.interval)
            .finish_non_exhaustive()
    }
}

/// The run's side of the hook: remembers when it last called. A clock read costs as much as
/// a time point of a small digital design, so once ticks come fast (16 reads in a row less
/// than a hundredth of the interval apart) the clock is read every `stride` ticks only, the
/// stride doubling (up to 1024) while reads stay that close and halving when one is more
/// than an eighth of the interval after the last.
pub(crate) struct Throttle {
    hook: Option<ProgressHook>,
    last: Instant,
    last_read: Instant,
    stride: u32,
    countdown: u32,
    fast_reads: u32,
}

impl Throttle {
    pub fn new(hook: Option<ProgressHook>) -> Throttle {
        let now = Instant::now();
        Throttle {
            hook,
            last: now,
            last_read: now,
            stride: 1,
            countdown: 1,
            fast_reads: 0,
        }
    }

    /// Reports `t` when the interval has passed since the last call (or since the start).
    #[inline]
    pub fn tick(&mut self, t: f64) {
        if self.hook.is_none() {
            return;
        }
        self.countdown -= 1;
        if self.countdown == 0 {
            self.read_clock(t);
        }
    }

    #[inline(never)]
    fn read_clock(&mut self, t: f64) {
        let Some(hook) = &self.hook else {
            return;
        };
        let now = Instant::now();
        let since = now.duration_since(self.last_read);
        self.last_read = now;
        if since < hook.interval / 100 {
            self.fast_reads = self.fast_reads.saturating_add(1);
            if self.fast_reads >= 16 {
                self.stride = (self.stride * 2).min(1024);
            }
        } else {
            self.fast_reads = 0;
            if since > hook.interval / 8 {
                self.stride = (self.stride / 2).max(1);
            }
        }
        self.countdown = self.stride;
        if now.duration_since(self.last) >= hook.interval {
            self.last = now;
            (hook.callback)(t);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::Mutex;

    #[test]
    fn calls_are_spaced_by_the_interval() {
        let seen = Arc::new(Mutex::new(Vec::new()));
        let sink = seen.clone();
        let hook = ProgressHook::every(Duration::from_millis(20), move |t| {
            sink.lock().unwrap().push(t)
        });
        let mut throttle = Throttle::new(Some(hook));
        throttle.tick(0.1); // too soon after the start
        std::thread::sleep(Duration::from_millis(25));
        throttle.tick(0.2);
        throttle.tick(0.3); // too soon after the last call
        std::thread::sleep(Duration::from_millis(25));
        throttle.tick(0.4);
        assert_eq!(*seen.lock().unwrap(), [0.2, 0.4]);
        Throttle::new(None).tick(1.0); // no hook: nothing to call
        // Fast ticks read the clock less often, and still call about once per interval.
        let calls = Arc::new(Mutex::new(0usize));
        let count = calls.clone();
        let hook = ProgressHook::every(Duration::from_millis(5), move |_| {
            *count.lock().unwrap() += 1
        });
        let mut throttle = Throttle::new(Some(hook));
        let start = Instant::now();
        while start.elapsed() < Duration::from_millis(60) {
            throttle.tick(0.5);
        }
        assert!(throttle.stride > 1);
        let n = *calls.lock().unwrap();
        assert!((2..=12).contains(&n), "{n} calls in 60 ms at one per 5 ms");
        assert!(format!("{:?}", ProgressHook::new(|_| {})).contains("50ms"));
    }
}
