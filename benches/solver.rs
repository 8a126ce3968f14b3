//! Solver benchmarks: transient of an RC ladder (N = 100, 1000, 10000 sections), the
//! operating point (damped Newton) of a diode-loaded resistor ladder, and the dense/sparse LU
//! crossover on N-node ladder matrices.
//!
//! Run: `cargo bench --bench solver` (or `-- crossover`, `-- ladder`, `-- diode`).

use std::hint::black_box;
use std::time::Duration;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use vams::solver::{
    Advance, DaeSystem, LinearOptions, LinearSolver, OpOptions, Tolerances, Transient,
    TransientOptions, operating_point,
};

/// RC ladder: a unit step source drives node 1 through R; node k has C to ground and R to
/// node k+1. `C v_k' + (v_k - v_{k-1})/R + (v_k - v_{k+1})/R = 0`, all unknowns differential.
struct RcLadder {
    n: usize,
    g: f64,
    c: f64,
    diff: Vec<bool>,
    pattern: Vec<(usize, usize)>,
}

impl RcLadder {
    fn new(n: usize) -> Self {
        let mut pattern = Vec::with_capacity(3 * n);
        for k in 0..n {
            if k > 0 {
                pattern.push((k, k - 1));
            }
            pattern.push((k, k));
            if k + 1 < n {
                pattern.push((k, k + 1));
            }
        }
        Self {
            n,
            g: 1.0,
            c: 1.0,
            diff: vec![true; n],
            pattern,
        }
    }
}

impl DaeSystem for RcLadder {
    fn len(&self) -> usize {
        self.n
    }
    fn differential(&self) -> &[bool] {
        &self.diff
    }
    fn pattern(&self) -> &[(usize, usize)] {
        &self.pattern
    }
    fn residual(&mut self, _t: f64, x: &[f64], xdot: &[f64], out: &mut [f64]) {
        for k in 0..self.n {
            let left = if k == 0 { 1.0 } else { x[k - 1] };
            let mut i = self.c * xdot[k] + self.g * (x[k] - left);
            if k + 1 < self.n {
                i += self.g * (x[k] - x[k + 1]);
            }
            out[k] = i;
        }
    }
    fn jacobian(&mut self, _t: f64, _x: &[f64], _xd: &[f64], alpha: f64, out: &mut [f64]) {
        for (o, &(r, c)) in out.iter_mut().zip(&self.pattern) {
            *o = if r != c {
                -self.g
            } else if r + 1 < self.n {
                2.0 * self.g + alpha * self.c
            } else {
                self.g + alpha * self.c
            };
        }
    }
}

/// The same ladder at DC with a diode (Is = 1e-14 A, Vt = 25.85 mV) from every node to
/// ground and a 5 V source: a nonlinear operating point solved from zero.
struct DiodeLadder(RcLadder);

impl DaeSystem for DiodeLadder {
    fn len(&self) -> usize {
        self.0.n
    }
    fn differential(&self) -> &[bool] {
        &self.0.diff
    }
    fn pattern(&self) -> &[(usize, usize)] {
        &self.0.pattern
    }
    fn residual(&mut self, t: f64, x: &[f64], xdot: &[f64], out: &mut [f64]) {
        self.0.residual(t, x, xdot, out);
        out[0] -= 4.0 * self.0.g; // 5 V source instead of 1 V
        for (o, &v) in out.iter_mut().zip(x) {
            *o += 1e-14 * ((v / 0.02585).exp() - 1.0);
        }
    }
    fn jacobian(&mut self, t: f64, x: &[f64], xdot: &[f64], alpha: f64, out: &mut [f64]) {
        self.0.jacobian(t, x, xdot, alpha, out);
        for (o, &(r, c)) in out.iter_mut().zip(&self.0.pattern) {
            if r == c {
                *o += 1e-14 / 0.02585 * (x[r] / 0.02585).exp();
            }
        }
    }
}

fn diode_op(n: usize) -> usize {
    let mut sys = DiodeLadder(RcLadder::new(n));
    let tol = Tolerances::uniform(n, 1e-6, 1e-12);
    let mut x = vec![0.0; n];
    operating_point(&mut sys, 0.0, &mut x, &tol, &OpOptions::default())
        .map_or(0, |r| r.newton_iterations)
}

fn diode(c: &mut Criterion) {
    let mut group = c.benchmark_group("diode_ladder_op");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(3));
    for n in [100usize, 1000, 10000] {
        eprintln!("diode ladder N = {n}: {} Newton iterations", diode_op(n));
        group.throughput(Throughput::Elements(n as u64));
        group.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, &n| {
            b.iter(|| black_box(diode_op(n)))
        });
    }
    group.finish();
}

/// Integrates the ladder over 20 RC from rest; returns the accepted step count.
fn ladder_transient(n: usize) -> usize {
    let mut sys = RcLadder::new(n);
    let opts = TransientOptions {
        reltol: 1e-4,
        abstol: 1e-9,
        ..TransientOptions::default()
    };
    let x0 = vec![0.0; n];
    let Ok(mut tr) = Transient::new(&mut sys, 0.0, &x0, opts) else {
        return 0;
    };
    while let Ok(a) = tr.advance(&mut sys, 20.0) {
        if matches!(a, Advance::Reached(_)) {
            break;
        }
    }
    tr.stats().accepted_steps
}

fn transient(c: &mut Criterion) {
    let mut group = c.benchmark_group("ladder_transient");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(5));
    for n in [100usize, 1000, 10000] {
        eprintln!("ladder N = {n}: {} accepted steps", ladder_transient(n));
        group.throughput(Throughput::Elements(n as u64));
        group.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, &n| {
            b.iter(|| black_box(ladder_transient(n)))
        });
    }
    group.finish();
}

/// Factor + solve of an N-node ladder's Newton matrix on one path.
fn crossover(c: &mut Criterion) {
    let mut group = c.benchmark_group("crossover");
    group
        .sample_size(20)
        .measurement_time(Duration::from_secs(1))
        .warm_up_time(Duration::from_millis(300));
    for n in [4usize, 8, 10, 12, 16, 24, 32, 64, 128] {
        let mut sys = RcLadder::new(n);
        let mut values = vec![0.0; sys.pattern.len()];
        let x = vec![0.0; n];
        sys.jacobian(0.0, &x, &x, 1e3, &mut values);
        for (name, dense_max) in [("dense", usize::MAX), ("sparse", 0)] {
            let opts = LinearOptions {
                dense_max,
                ..LinearOptions::default()
            };
            let Ok(mut lin) = LinearSolver::new(n, &sys.pattern, opts) else {
                continue;
            };
            let mut rhs = vec![1.0; n];
            group.bench_with_input(BenchmarkId::new(name, n), &n, |b, _| {
                b.iter(|| {
                    let ok = lin.factor(black_box(&values), 0.0).is_ok();
                    rhs.fill(1.0);
                    ok && lin.solve_in_place(&mut rhs).is_ok()
                })
            });
        }
    }
    group.finish();
}

criterion_group!(benches, crossover, diode, transient);
criterion_main!(benches);
