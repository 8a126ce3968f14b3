//! Small DAEs with closed-form solutions, shared by the tests.

use crate::DaeSystem;

/// `M x' + K x = s * b`, with optional root functions `g_r = x[i_r] - level_r`.
pub struct LinearDae {
    pub m: Vec<Vec<f64>>,
    pub k: Vec<Vec<f64>>,
    pub b: Vec<f64>,
    /// Sources rise linearly: row `i` is driven by `s * (b_i + ramp_i * t)`.
    pub ramp: Vec<f64>,
    pub roots: Vec<(usize, f64)>,
    pub scale: f64,
    /// What `is_linear` reports (true: the solver may skip Newton's confirming iteration).
    pub linear: bool,
    diff: Vec<bool>,
    pattern: Vec<(usize, usize)>,
}

impl LinearDae {
    pub fn new(m: Vec<Vec<f64>>, k: Vec<Vec<f64>>, b: Vec<f64>) -> Self {
        let n = b.len();
        let diff = (0..n).map(|j| (0..n).any(|i| m[i][j] != 0.0)).collect();
        let pattern = (0..n)
            .flat_map(|i| (0..n).map(move |j| (i, j)))
            .filter(|&(i, j)| m[i][j] != 0.0 || k[i][j] != 0.0)
            .collect();
        Self {
            m,
            k,
            b,
            ramp: vec![0.0; n],
            roots: Vec::new(),
            scale: 1.0,
            linear: true,
            diff,
            pattern,
        }
    }

    /// RC low-pass: `x' = (u - x) / tau`.
    pub fn rc(tau: f64, u: f64) -> Self {
        Self::new(vec![vec![tau]], vec![vec![1.0]], vec![u])
    }

    /// Series R-L-C driven by a step `v`; unknowns `[i, v_c, v_b]` (`v_b` algebraic: the node
    /// between R and L). Equations: `v_b = v - R i`, `L i' = v_b - v_c`, `C v_c' = i`.
    pub fn rlc(r: f64, l: f64, c: f64, v: f64) -> Self {
        Self::new(
            vec![vec![0.0, 0.0, 0.0], vec![l, 0.0, 0.0], vec![0.0, c, 0.0]],
            vec![
                vec![r, 0.0, 1.0],
                vec![0.0, 1.0, -1.0],
                vec![-1.0, 0.0, 0.0],
            ],
            vec![v, 0.0, 0.0],
        )
    }

    /// LC tank: `L i' = v`, `C v' = -i`; unknowns `[i, v]`.
    pub fn lc(l: f64, c: f64) -> Self {
        Self::new(
            vec![vec![l, 0.0], vec![0.0, c]],
            vec![vec![0.0, -1.0], vec![1.0, 0.0]],
            vec![0.0, 0.0],
        )
    }
}

impl DaeSystem for LinearDae {
    fn len(&self) -> usize {
        self.b.len()
    }
    fn is_linear(&self) -> bool {
        self.linear
    }
    fn differential(&self) -> &[bool] {
        &self.diff
    }
    fn pattern(&self) -> &[(usize, usize)] {
        &self.pattern
    }
    fn residual(&mut self, t: f64, x: &[f64], xdot: &[f64], out: &mut [f64]) {
        for (i, o) in out.iter_mut().enumerate() {
            *o = -self.scale * (self.b[i] + self.ramp[i] * t);
            for j in 0..x.len() {
                *o += self.m[i][j] * xdot[j] + self.k[i][j] * x[j];
            }
        }
    }
    fn jacobian(&mut self, _t: f64, _x: &[f64], _xd: &[f64], alpha: f64, out: &mut [f64]) {
        for (o, &(i, j)) in out.iter_mut().zip(&self.pattern) {
            *o = self.k[i][j] + alpha * self.m[i][j];
        }
    }
    fn root_count(&self) -> usize {
        self.roots.len()
    }
    fn roots(&mut self, _t: f64, x: &[f64], _xdot: &[f64], out: &mut [f64]) {
        for (o, &(i, level)) in out.iter_mut().zip(&self.roots) {
            *o = x[i] - level;
        }
    }
    fn set_source_scale(&mut self, s: f64) {
        self.scale = s;
    }
}

/// Source `vs` through `r` into a diode to ground: unknowns `[v1, v2]`,
/// `v1 = s * vs`, `(v2 - v1)/r + is (exp(v2/vt) - 1) = 0`.
pub struct DiodeCircuit {
    pub vs: f64,
    pub r: f64,
    pub is: f64,
    pub vt: f64,
    pub scale: f64,
}

impl DiodeCircuit {
    pub const PATTERN: [(usize, usize); 3] = [(0, 0), (1, 0), (1, 1)];
}

impl DaeSystem for DiodeCircuit {
    fn len(&self) -> usize {
        2
    }
    fn differential(&self) -> &[bool] {
        &[false, false]
    }
    fn pattern(&self) -> &[(usize, usize)] {
        &Self::PATTERN
    }
    fn residual(&mut self, _t: f64, x: &[f64], _xd: &[f64], out: &mut [f64]) {
        out[0] = x[0] - self.scale * self.vs;
        out[1] = (x[1] - x[0]) / self.r + self.is * ((x[1] / self.vt).exp() - 1.0);
    }
    fn jacobian(&mut self, _t: f64, x: &[f64], _xd: &[f64], _alpha: f64, out: &mut [f64]) {
        out[0] = 1.0;
        out[1] = -1.0 / self.r;
        out[2] = 1.0 / self.r + self.is / self.vt * (x[1] / self.vt).exp();
    }
    fn set_source_scale(&mut self, s: f64) {
        self.scale = s;
    }
}

/// A purely algebraic system given by closures, for failure cases.
pub struct Algebraic<F, J> {
    pub n: usize,
    pub pattern: Vec<(usize, usize)>,
    pub diff: Vec<bool>,
    pub f: F,
    pub j: J,
}

impl<F, J> DaeSystem for Algebraic<F, J>
where
    F: FnMut(&[f64], &mut [f64]),
    J: FnMut(&[f64], &mut [f64]),
{
    fn len(&self) -> usize {
        self.n
    }
    fn differential(&self) -> &[bool] {
        &self.diff
    }
    fn pattern(&self) -> &[(usize, usize)] {
        &self.pattern
    }
    fn residual(&mut self, _t: f64, x: &[f64], _xd: &[f64], out: &mut [f64]) {
        (self.f)(x, out);
    }
    fn jacobian(&mut self, _t: f64, x: &[f64], _xd: &[f64], _alpha: f64, out: &mut [f64]) {
        (self.j)(x, out);
    }
}
