//! Tests of the numerical core against closed forms, with stated tolerances.

mod accuracy;
mod events;
mod init;
mod linear;
mod newton;
mod op;
mod systems;
mod transient;
