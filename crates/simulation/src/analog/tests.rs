//! Tests of the analog engine on hand-built designs (the elaborator is written in parallel).

mod circuits;
mod fixture;
mod jacobian;
mod listing;
mod mechanics;
mod perf;
mod small_signal;
mod structural;
