//! Monte Carlo samples: each parameter's distribution by its inverse CDF applied to a uniform
//! number, the uniforms from a ChaCha8 stream per sample (seeded by the spec's seed, the
//! stream numbered by the sample), optionally stratified (Latin hypercube) and correlated
//! (a Gaussian copula: the uniforms' normal scores mixed by the Cholesky factor of the
//! correlation matrix).
//!
//! ChaCha8 is specified bit for bit and the inverse CDFs are plain floating-point arithmetic,
//! so sample `k` is the same on any machine, in any shard and in any order.

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use statrs::distribution::{ContinuousCDF, Normal};

/// A parameter's distribution.
#[derive(Clone, Debug, PartialEq)]
pub enum Distribution {
    Normal {
        mean: f64,
        sigma: f64,
    },
    Uniform {
        min: f64,
        max: f64,
    },
    /// `ln x` normal with median `median` and standard deviation `sigma`.
    LogNormal {
        median: f64,
        sigma: f64,
    },
    /// The normal restricted to `[min, max]`.
    TruncatedNormal {
        mean: f64,
        sigma: f64,
        min: f64,
        max: f64,
    },
}

/// How the uniforms are drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sampling {
    Random,
    /// Each parameter's range cut into N strata of equal probability, one sample in each.
    LatinHypercube,
}

/// The most samples a Latin hypercube holds (its strata are kept as one permutation per
/// parameter, 4 bytes per sample).
pub const MAX_LATIN_HYPERCUBE: usize = 10_000_000;

fn standard_normal() -> Normal {
    // An invariant: mean 0 and sigma 1 are valid parameters.
    Normal::new(0.0, 1.0).expect("the standard normal")
}

impl Distribution {
    /// The value at cumulative probability `u` in (0, 1).
    pub fn quantile(&self, u: f64) -> f64 {
        let z = || standard_normal().inverse_cdf(u);
        match *self {
            Distribution::Normal { mean, sigma } => mean + sigma * z(),
            Distribution::Uniform { min, max } => min + u * (max - min),
            Distribution::LogNormal { median, sigma } => median * (sigma * z()).exp(),
            Distribution::TruncatedNormal {
                mean,
                sigma,
                min,
                max,
            } => {
                if sigma == 0.0 {
                    return mean.clamp(min, max);
                }
                let n = standard_normal();
                let (a, b) = (n.cdf((min - mean) / sigma), n.cdf((max - mean) / sigma));
                let x = mean + sigma * n.inverse_cdf(a + u * (b - a));
                // Rounding at the far tails must not leave the interval.
                x.clamp(min, max)
            }
        }
    }

    /// The nominal value: the mean, the middle, the median; a truncated normal's mean clamped
    /// into its interval.
    pub fn nominal(&self) -> f64 {
        match *self {
            Distribution::Normal { mean, .. } => mean,
            Distribution::Uniform { min, max } => 0.5 * (min + max),
            Distribution::LogNormal { median, .. } => median,
            Distribution::TruncatedNormal { mean, min, max, .. } => mean.clamp(min, max),
        }
    }
}

/// Why a sampler cannot be built.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum SamplerError {
    #[error("the correlation matrix is not positive definite")]
    NotPositiveDefinite,
    #[error("a Latin hypercube holds at most {MAX_LATIN_HYPERCUBE} samples, not {0}")]
    TooManyForLatinHypercube(usize),
}

/// The samples of a Monte Carlo plan.
#[derive(Clone, Debug)]
pub struct Sampler {
    names: Vec<String>,
    distributions: Vec<Distribution>,
    runs: usize,
    seed: u64,
    sampling: Sampling,
    /// The lower Cholesky factor of the correlation matrix, row by row; `None`: independent.
    cholesky: Option<Vec<Vec<f64>>>,
    /// Per parameter, the stratum of each sample (Latin hypercube only).
    strata: Vec<Vec<u32>>,
}

/// A uniform number in (0, 1), never 0 or 1 (the inverse CDFs are infinite there).
fn open_unit(rng: &mut ChaCha8Rng) -> f64 {
    ((rng.random::<u64>() >> 11) as f64 + 0.5) / (1u64 << 53) as f64
}

impl Sampler {
    /// `correlation`: the full symmetric matrix, 1 on the diagonal, or `None`.
    pub fn new(
        parameters: Vec<(String, Distribution)>,
        runs: usize,
        seed: u64,
        sampling: Sampling,
        correlation: Option<Vec<Vec<f64>>>,
    ) -> Result<Sampler, SamplerError> {
        let (names, distributions): (Vec<_>, Vec<_>) = parameters.into_iter().unzip();
        let cholesky = correlation.map(|c| cholesky(&c)).transpose()?;
        let strata = match sampling {
            Sampling::Random => Vec::new(),
            Sampling::LatinHypercube if runs > MAX_LATIN_HYPERCUBE => {
                return Err(SamplerError::TooManyForLatinHypercube(runs));
            }
            Sampling::LatinHypercube => (0..names.len())
                .map(|p| {
                    // A stream of its own per parameter, far from the samples' streams.
                    let mut rng = ChaCha8Rng::seed_from_u64(seed);
                    rng.set_stream(u64::MAX - p as u64);
                    let mut order: Vec<u32> = (0..runs as u32).collect();
                    // Fisher-Yates.
                    for i in (1..order.len()).rev() {
                        let j = rng.random_range(0..=i);
                        order.swap(i, j);
                    }
                    order
                })
                .collect(),
        };
        Ok(Sampler {
            names,
            distributions,
            runs,
            seed,
            sampling,
            cholesky,
            strata,
        })
    }

    pub fn names(&self) -> Vec<String> {
        self.names.clone()
    }

    pub fn runs(&self) -> usize {
        self.runs
    }

    pub fn sampling(&self) -> Sampling {
        self.sampling
    }

    pub fn nominal(&self) -> Vec<f64> {
        self.distributions
            .iter()
            .map(Distribution::nominal)
            .collect()
    }

    /// Sample `k` (from 0): a value per parameter.
    pub fn sample(&self, k: usize) -> Vec<f64> {
        let mut rng = ChaCha8Rng::seed_from_u64(self.seed);
        rng.set_stream(k as u64);
        let mut u: Vec<f64> = (0..self.names.len())
            .map(|p| {
                let v = open_unit(&mut rng);
                match self.strata.get(p) {
                    Some(strata) => (f64::from(strata[k]) + v) / self.runs as f64,
                    None => v,
                }
            })
            .collect();
        if let Some(l) = &self.cholesky {
            let n = standard_normal();
            let z: Vec<f64> = u.iter().map(|&x| n.inverse_cdf(x)).collect();
            for (i, row) in l.iter().enumerate() {
                let mixed: f64 = row.iter().zip(&z).map(|(a, b)| a * b).sum();
                // Kept inside (0, 1): cdf rounds to 1 beyond z = 8.3.
                u[i] = n
                    .cdf(mixed)
                    .clamp(f64::MIN_POSITIVE, 1.0 - f64::EPSILON / 2.0);
            }
        }
        self.distributions
            .iter()
            .zip(u)
            .map(|(d, u)| d.quantile(u))
            .collect()
    }
}

/// The lower Cholesky factor of a small symmetric matrix (a correlation matrix of a few
/// parameters), by faer.
fn cholesky(c: &[Vec<f64>]) -> Result<Vec<Vec<f64>>, SamplerError> {
    let n = c.len();
    let m = faer::Mat::from_fn(n, n, |i, j| c[i][j]);
    let llt = m
        .llt(faer::Side::Lower)
        .map_err(|_| SamplerError::NotPositiveDefinite)?;
    let l = llt.L();
    Ok((0..n)
        .map(|i| {
            (0..n)
                .map(|j| if j <= i { l[(i, j)] } else { 0.0 })
                .collect()
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn mean_sigma(x: &[f64]) -> (f64, f64) {
        let n = x.len() as f64;
        let m = x.iter().sum::<f64>() / n;
        let v = x.iter().map(|a| (a - m).powi(2)).sum::<f64>() / (n - 1.0);
        (m, v.sqrt())
    }

    fn sampler(sampling: Sampling, corr: Option<Vec<Vec<f64>>>) -> Sampler {
        Sampler::new(
            vec![
                (
                    "r".into(),
                    Distribution::Normal {
                        mean: 5.0,
                        sigma: 0.5,
                    },
                ),
                ("j".into(), Distribution::Uniform { min: 1.0, max: 3.0 }),
            ],
            4000,
            42,
            sampling,
            corr,
        )
        .unwrap()
    }

    #[test]
    fn the_same_seed_gives_the_same_samples_in_any_order() {
        let s = sampler(Sampling::Random, None);
        let forward: Vec<Vec<f64>> = (0..50).map(|k| s.sample(k)).collect();
        let backward: Vec<Vec<f64>> = (0..50).rev().map(|k| s.sample(k)).collect();
        assert!(forward.iter().eq(backward.iter().rev()));
        // Pinned: these are the numbers on every machine (ChaCha8 is specified bit for bit).
        let again = sampler(Sampling::Random, None);
        assert_eq!(s.sample(7), again.sample(7));
        let other = Sampler::new(
            vec![(
                "r".into(),
                Distribution::Normal {
                    mean: 5.0,
                    sigma: 0.5,
                },
            )],
            10,
            43,
            Sampling::Random,
            None,
        )
        .unwrap();
        assert_ne!(other.sample(7)[0], s.sample(7)[0]);
    }

    #[test]
    fn the_samples_follow_their_distributions() {
        for sampling in [Sampling::Random, Sampling::LatinHypercube] {
            let s = sampler(sampling, None);
            let all: Vec<Vec<f64>> = (0..s.runs()).map(|k| s.sample(k)).collect();
            let r: Vec<f64> = all.iter().map(|x| x[0]).collect();
            let j: Vec<f64> = all.iter().map(|x| x[1]).collect();
            let (m, sd) = mean_sigma(&r);
            // 4 000 samples: the mean's standard error is 0.5/63 = 0.008.
            assert!(
                (m - 5.0).abs() < 0.04 && (sd - 0.5).abs() < 0.03,
                "{m} {sd}"
            );
            assert!(j.iter().all(|&x| (1.0..=3.0).contains(&x)));
            let (m, sd) = mean_sigma(&j);
            assert!((m - 2.0).abs() < 0.04 && (sd - 2.0 / 12f64.sqrt()).abs() < 0.03);
        }
    }

    #[test]
    fn a_latin_hypercube_puts_one_sample_in_each_stratum() {
        let s = sampler(Sampling::LatinHypercube, None);
        for p in 0..2 {
            let mut seen = vec![false; s.runs()];
            for k in 0..s.runs() {
                let x = s.sample(k)[p];
                let u = match p {
                    0 => standard_normal().cdf((x - 5.0) / 0.5),
                    _ => (x - 1.0) / 2.0,
                };
                let stratum = ((u * s.runs() as f64) as usize).min(s.runs() - 1);
                assert!(!seen[stratum], "two samples in stratum {stratum}");
                seen[stratum] = true;
            }
        }
    }

    #[test]
    fn correlated_samples_have_the_asked_correlation() {
        let s = sampler(Sampling::Random, Some(vec![vec![1.0, 0.8], vec![0.8, 1.0]]));
        let all: Vec<Vec<f64>> = (0..s.runs()).map(|k| s.sample(k)).collect();
        let r: Vec<f64> = all.iter().map(|x| x[0]).collect();
        let j: Vec<f64> = all.iter().map(|x| x[1]).collect();
        let ((mr, sr), (mj, sj)) = (mean_sigma(&r), mean_sigma(&j));
        let cov = r
            .iter()
            .zip(&j)
            .map(|(a, b)| (a - mr) * (b - mj))
            .sum::<f64>()
            / (r.len() as f64 - 1.0);
        let rho = cov / (sr * sj);
        // The Pearson correlation of a normal and a uniform under a Gaussian copula of 0.8
        // is 0.8 * sqrt(3/pi) = 0.78.
        assert!((rho - 0.78).abs() < 0.03, "{rho}");
        assert_eq!(
            Sampler::new(
                vec![],
                1,
                1,
                Sampling::Random,
                Some(vec![vec![1.0, 1.5], vec![1.5, 1.0]])
            )
            .unwrap_err(),
            SamplerError::NotPositiveDefinite
        );
    }

    #[test]
    fn quantiles_of_each_distribution() {
        let ln = Distribution::LogNormal {
            median: 2.0,
            sigma: 0.1,
        };
        assert!((ln.quantile(0.5) - 2.0).abs() < 1e-12);
        assert!((ln.quantile(0.975) - 2.0 * (0.1f64 * 1.959964).exp()).abs() < 1e-5);
        let t = Distribution::TruncatedNormal {
            mean: 0.0,
            sigma: 1.0,
            min: -1.0,
            max: 2.0,
        };
        assert!(t.quantile(1e-12) >= -1.0 && t.quantile(1.0 - 1e-12) <= 2.0);
        assert!(
            (t.quantile(0.5) - 0.171164).abs() < 1e-5,
            "{}",
            t.quantile(0.5)
        );
        assert_eq!(t.nominal(), 0.0);
    }
}
