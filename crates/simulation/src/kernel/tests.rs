//! Kernel tests on hand-built designs: the event kernel on digital designs, the mixed-signal
//! cycle on small analog systems with closed-form solutions.

mod build;
mod calls;
mod digital;
mod expr_dae;
mod mixed;
