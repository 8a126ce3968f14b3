//! Looking up channels and reshaping a capture in time: trigger, shift, window, decimate.

use super::error::MissingChannel;
use super::{Capture, CaptureError, Channel, closest, text};

impl Capture {
    /// Number of samples.
    pub fn len(&self) -> usize {
        self.time.len()
    }

    /// Whether there are no samples.
    pub fn is_empty(&self) -> bool {
        self.time.is_empty()
    }

    /// The channel named `name`: case-insensitive, without the unit of a header written
    /// `name (unit)` or `name[unit]`; `1` and `CH1`, `Channel A` and `ch a` are the same.
    pub fn channel(&self, name: &str) -> Option<&Channel> {
        let k = text::key(name);
        self.channels.iter().find(|c| text::key(&c.name) == k)
    }

    /// The channel named `name`, or an error listing the channels there are.
    pub fn channel_or_error(&self, name: &str) -> Result<&Channel, CaptureError> {
        self.channel(name).ok_or_else(|| {
            let names = self.channels.iter().map(|c| c.name.as_str());
            CaptureError::MissingChannel(Box::new(MissingChannel {
                path: self.path.clone(),
                channel: name.to_string(),
                found: names.clone().map(String::from).collect(),
                suggestion: closest(name, names),
                src: None,
                span: None,
            }))
        })
    }

    /// The first time `channel` crosses `level` upwards (`rising`) or downwards, interpolated
    /// between the samples either side; `None` if it never does or there is no such channel.
    pub fn trigger_time(&self, channel: &str, level: f64, rising: bool) -> Option<f64> {
        let v = &self.channel(channel)?.values;
        (1..v.len().min(self.time.len())).find_map(|k| {
            let (a, b) = (v[k - 1], v[k]);
            let crosses = if rising {
                a < level && b >= level
            } else {
                a > level && b <= level
            };
            crosses.then(|| {
                let f = (level - a) / (b - a);
                self.time[k - 1] + f * (self.time[k] - self.time[k - 1])
            })
        })
    }

    /// The capture with `dt` added to every time (`shifted(-t0)` puts t0 at zero).
    pub fn shifted(&self, dt: f64) -> Capture {
        let mut c = self.clone();
        c.time.iter_mut().for_each(|t| *t += dt);
        c
    }

    /// The samples with `from <= time <= to` (the warnings stay the whole capture's).
    pub fn window(&self, from: f64, to: f64) -> Capture {
        let a = self.time.partition_point(|&t| t < from);
        let b = self.time.partition_point(|&t| t <= to).max(a);
        self.select(a, b)
    }

    fn select(&self, a: usize, b: usize) -> Capture {
        Capture {
            path: self.path.clone(),
            time: self.time[a..b].to_vec(),
            channels: self
                .channels
                .iter()
                .map(|c| Channel {
                    name: c.name.clone(),
                    unit: c.unit.clone(),
                    values: c.values[a..b].to_vec(),
                    clipped: c.clipped[a..b].to_vec(),
                })
                .collect(),
            warnings: self.warnings.clone(),
            header: self.header.clone(),
        }
    }

    /// At most `max_points` samples: the means of consecutive blocks of equal size (the last
    /// may be shorter), each at its samples' mean time, clipped if any of its samples is.
    /// The capture itself when it is short enough (or `max_points` is 0).
    pub fn decimated(&self, max_points: usize) -> Capture {
        let n = self.time.len();
        if max_points == 0 || n <= max_points {
            return self.clone();
        }
        let block = n.div_ceil(max_points);
        let mean = |s: &[f64]| s.iter().sum::<f64>() / s.len() as f64;
        Capture {
            path: self.path.clone(),
            time: self.time.chunks(block).map(mean).collect(),
            channels: self
                .channels
                .iter()
                .map(|c| Channel {
                    name: c.name.clone(),
                    unit: c.unit.clone(),
                    values: c.values.chunks(block).map(mean).collect(),
                    clipped: c
                        .clipped
                        .chunks(block)
                        .map(|b| b.iter().any(|x| *x))
                        .collect(),
                })
                .collect(),
            warnings: self.warnings.clone(),
            header: self.header.clone(),
        }
    }
}
