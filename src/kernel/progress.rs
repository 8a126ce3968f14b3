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

/// The run's side of the hook: remembers when it last called.
pub(crate) struct Throttle {
    hook: Option<ProgressHook>,
    last: Instant,
}

impl Throttle {
    pub fn new(hook: Option<ProgressHook>) -> Throttle {
        Throttle {
            hook,
            last: Instant::now(),
        }
    }

    /// Reports `t` when the interval has passed since the last call (or since the start).
    pub fn tick(&mut self, t: f64) {
        let Some(hook) = &self.hook else {
            return;
        };
        let now = Instant::now();
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
        assert!(format!("{:?}", ProgressHook::new(|_| {})).contains("50ms"));
    }
}
