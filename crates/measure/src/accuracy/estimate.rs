//! What a row's seeds tell: its MSE, bias² and variance, each with its
//! standard error.
//!
//! A row is K renders X₁ … X_K of one setting with independent seeds,
//! measured against the reference R. Write dₖ = Xₖ − R for a render's
//! error picture and c_jk = ⟨d_j, d_k⟩ for the mean, over every value (each
//! channel of each pixel), of d_j · d_k. Everything below comes from the
//! K × K matrix c ([`split`]):
//!
//! - **MSE** = (1/K) Σₖ c_kk, the mean of the renders' own MSEs.
//! - **bias²** = (1/(K(K−1))) Σ_{j≠k} c_jk. Two renders with independent
//!   seeds have independent noise, so the mean of the product of their
//!   errors is the product of their mean errors, value by value:
//!   E[d_j · d_k] = (E d)², the squared bias. No render is multiplied by
//!   itself, so no noise is squared into it. (It equals ‖X̄ − R‖² − V/K:
//!   the seeds' mean's distance, less what its noise adds.)
//! - **variance** V = MSE − bias² = (1/(2K(K−1))) Σ_{j≠k} ‖X_j − X_k‖²:
//!   half the mean squared difference of two renders, in which R cancels.
//!
//! The reference is one more render with noise of its own, independent of
//! every row's: so E[c_jk] = b² + σ_R², and a bias² of zero reads as the
//! reference's floor σ_R² ([`super::summary::Floor`]), not as 0.
//!
//! **Standard errors.** The seeds are the independent units, so each SE
//! is taken over them, with no model of a pixel's noise (edges,
//! fireflies). The MSE is a mean of K independent renders' MSEs: its SE is
//! s/√K. bias² and variance are each an average over the K(K−1)/2 pairs of
//! seeds of a kernel h_jk (d_j·d_k for bias², ½(d_j − d_k)² for the
//! variance): a U-statistic of order 2, whose variance is (Hoeffding 1948)
//!
//! Var = (4(K−2) ζ₁ + 2 ζ₂) / (K(K−1)),
//!
//! ζ₂ = Var(h_jk), ζ₁ = Cov(h_jk, h_jl) for pairs that share one seed. Both
//! are estimated without bias from the pairs: the mean of h_jk² over pairs
//! (m₂), of h_jk·h_jl over pairs sharing a seed (m₁), and of h_jk·h_lm over
//! disjoint pairs (m₀, the squared mean): ζ₂ = m₂ − m₀, ζ₁ = m₁ − m₀.
//! From a handful of seeds that estimate is noisy, often below 0; but each
//! pixel draws its rays independently of every other, so the picture's
//! statistic is the mean of P independent pixels' and its variance is
//! Σ_p Var_p / P²: the estimate is made pixel by pixel (its three channels
//! together, since they come from the same rays) and summed, where the
//! noise of thousands of pixels averages out. (The jackknife over seeds,
//! tried first, overstates this variance by 2(K−1)/(K−2), 2.5 at K = 6,
//! exactly where bias² is zero and the floor is judged: the test below
//! shows both. It is kept as the fallback where the sum is ≤ 0.) It needs
//! K ≥ 4, for disjoint pairs. It is an SE given this reference: the
//! reference's own error is the floor, reported apart.

/// A value measured over seeds, with its standard error.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Estimate {
    pub value: f64,
    /// The standard error: how far another set of K seeds would typically
    /// put `value`.
    pub se: f64,
}

impl Estimate {
    /// A value known exactly (a render without randomness).
    pub fn exact(value: f64) -> Estimate {
        Estimate { value, se: 0.0 }
    }
}

impl std::fmt::Display for Estimate {
    /// "1.23e-4 ± 4.5e-6", or the value alone when it is exact.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.se > 0.0 {
            write!(f, "{:.2e} ± {:.1e}", self.value, self.se)
        } else {
            write!(f, "{:.2e}", self.value)
        }
    }
}

/// A row's MSE and its split, each with its standard error.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Split {
    pub mse: Estimate,
    pub bias2: Estimate,
    pub variance: Estimate,
}

/// The split of `errors`, each render's error picture X − R as a flat list
/// of values, three (a pixel's channels) after three, all of one length.
pub fn split(errors: &[Vec<f32>]) -> Split {
    let k = errors.len();
    let values = errors.first().map_or(0, Vec::len);
    let pixels = (values / 3).max(1);
    // The whole picture's products c_jk, for the MSE and the fallback.
    let mut c = vec![vec![0.0; k]; k];
    let (mut bias2, mut variance) = (PairMean::default(), PairMean::default());
    for p in 0..pixels {
        let cp = pixel_products(errors, p);
        for (row, row_p) in c.iter_mut().zip(&cp) {
            for (x, y) in row.iter_mut().zip(row_p) {
                *x += y / pixels as f64;
            }
        }
        bias2.add(&bias_kernel(&cp), pixels);
        variance.add(&variance_kernel(&cp), pixels);
    }
    Split {
        mse: mean_with_se(&(0..k).map(|i| c[i][i]).collect::<Vec<_>>()),
        bias2: bias2.estimate(&bias_kernel(&c)),
        variance: variance.estimate(&variance_kernel(&c)),
    }
}

/// c_jk for pixel `p`: the mean over its three channels of d_j · d_k.
fn pixel_products(errors: &[Vec<f32>], p: usize) -> Vec<Vec<f64>> {
    let channels = |e: &Vec<f32>| -> [f64; 3] {
        let at = |i: usize| e.get(3 * p + i).map_or(0.0, |&v| f64::from(v));
        [at(0), at(1), at(2)]
    };
    let d: Vec<[f64; 3]> = errors.iter().map(channels).collect();
    d.iter()
        .map(|a| {
            d.iter()
                .map(|b| (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / 3.0)
                .collect()
        })
        .collect()
}

/// bias²'s kernel: h_jk = c_jk (the diagonal unused).
fn bias_kernel(c: &[Vec<f64>]) -> Vec<Vec<f64>> {
    c.to_vec()
}

/// The variance's kernel: h_jk = ½(c_jj + c_kk) − c_jk = ½(d_j − d_k)².
fn variance_kernel(c: &[Vec<f64>]) -> Vec<Vec<f64>> {
    (0..c.len())
        .map(|j| {
            (0..c.len())
                .map(|k| 0.5 * (c[j][j] + c[k][k]) - c[j][k])
                .collect()
        })
        .collect()
}

/// A mean over pixels of each pixel's mean over pairs, and the sum of
/// their variances: the picture's U-statistic and its variance.
#[derive(Default)]
struct PairMean {
    value: f64,
    variance: f64,
}

impl PairMean {
    /// Adds one of `pixels` pixels, its kernel `h`.
    fn add(&mut self, h: &[Vec<f64>], pixels: usize) {
        let all: Vec<usize> = (0..h.len()).collect();
        let n = pixels as f64;
        self.value += mean_off_diagonal(h, &all) / n;
        self.variance += u_statistic_variance(h).unwrap_or(0.0) / (n * n);
    }

    /// The estimate; where the summed variance is not above 0 (too few
    /// seeds or pixels), the jackknife's SE of `whole`, the picture's kernel.
    fn estimate(&self, whole: &[Vec<f64>]) -> Estimate {
        let se = if self.variance > 0.0 && whole.len() >= 4 {
            self.variance.sqrt()
        } else {
            jackknife(whole)
        };
        Estimate {
            value: self.value,
            se,
        }
    }
}

/// The mean of `values` and its SE, s/√K (infinite for fewer than two).
fn mean_with_se(values: &[f64]) -> Estimate {
    let k = values.len();
    let value = values.iter().sum::<f64>() / k.max(1) as f64;
    let se = if k > 1 {
        let squares: f64 = values.iter().map(|v| (v - value) * (v - value)).sum();
        (squares / ((k - 1) * k) as f64).sqrt()
    } else {
        f64::INFINITY
    };
    Estimate { value, se }
}

/// The variance of the mean over pairs of the symmetric kernel `h` (its
/// diagonal unused), estimated without bias: (4(K−2)ζ₁ + 2ζ₂)/(K(K−1)).
/// `None` for fewer than 4 seeds.
fn u_statistic_variance(h: &[Vec<f64>]) -> Option<f64> {
    let k = h.len();
    if k < 4 {
        return None;
    }
    let kf = k as f64;
    // P: the sum over pairs; Q: of squares; T: over two pairs that share
    // one seed; D: over two disjoint pairs (from P² = Q + 2T + 2D).
    let (mut p, mut q, mut rows) = (0.0, 0.0, 0.0);
    for (j, row) in h.iter().enumerate() {
        let mut sum = 0.0;
        for (i, &x) in row.iter().enumerate() {
            if i != j {
                sum += x;
                if i > j {
                    p += x;
                    q += x * x;
                }
            }
        }
        rows += sum * sum;
    }
    let t = (rows - 2.0 * q) / 2.0;
    let d = (p * p - q - 2.0 * t) / 2.0;
    let m2 = q / (kf * (kf - 1.0) / 2.0);
    let m1 = t / (kf * (kf - 1.0) * (kf - 2.0) / 2.0);
    let m0 = d / (kf * (kf - 1.0) * (kf - 2.0) * (kf - 3.0) / 8.0);
    let (zeta1, zeta2) = (m1 - m0, m2 - m0);
    Some((4.0 * (kf - 2.0) * zeta1 + 2.0 * zeta2) / (kf * (kf - 1.0)))
}

/// The jackknife SE of the mean over pairs of `h`: θ₋ₖ without seed k,
/// SE² = ((K−1)/K) Σₖ (θ₋ₖ − θ̄)². Infinite for fewer than 3 seeds.
fn jackknife(h: &[Vec<f64>]) -> f64 {
    let k = h.len();
    if k < 3 {
        return f64::INFINITY;
    }
    let all: Vec<usize> = (0..k).collect();
    let left_out: Vec<f64> = (0..k)
        .map(|out| {
            let rest: Vec<usize> = all.iter().copied().filter(|&i| i != out).collect();
            mean_off_diagonal(h, &rest)
        })
        .collect();
    let mean = left_out.iter().sum::<f64>() / k as f64;
    let squares: f64 = left_out.iter().map(|t| (t - mean) * (t - mean)).sum();
    ((k as f64 - 1.0) / k as f64 * squares).sqrt()
}

/// (1/(K(K−1))) Σ_{j≠k} c_jk over `seeds` (0 for fewer than two).
fn mean_off_diagonal(c: &[Vec<f64>], seeds: &[usize]) -> f64 {
    let k = seeds.len();
    if k < 2 {
        return 0.0;
    }
    let mut sum = 0.0;
    for &j in seeds {
        for &i in seeds {
            if i != j {
                sum += c[j][i];
            }
        }
    }
    sum / (k * (k - 1)) as f64
}

#[cfg(test)]
mod tests {
    use super::*;
    use test_support::Rng;

    /// The whole picture's c_jk, as the jackknife takes it.
    fn products(errors: &[Vec<f32>]) -> Vec<Vec<f64>> {
        let n = errors[0].len() as f64;
        let dot = |a: &[f32], b: &[f32]| {
            a.iter()
                .zip(b)
                .map(|(&x, &y)| f64::from(x) * f64::from(y))
                .sum::<f64>()
                / n
        };
        errors
            .iter()
            .map(|a| errors.iter().map(|b| dot(a, b)).collect())
            .collect()
    }

    /// K renders of `n` values, each value `bias` plus uniform noise on
    /// [−a, a] (variance a²/3), against a reference of 0.
    fn renders(rng: &mut Rng, k: usize, n: usize, bias: f32, a: f32) -> Vec<Vec<f32>> {
        (0..k)
            .map(|_| (0..n).map(|_| bias + rng.range(-a, a)).collect())
            .collect()
    }

    #[test]
    fn the_split_is_exact_and_the_mses_se_is_the_sd_over_root_k() {
        // One value a pixel (the other two channels 0, so ×√3 here; in
        // f32, so equal to 1e-6).
        let pixel = |a: f32, b: f32| vec![a, 0.0, 0.0, b, 0.0, 0.0];
        let errors = [(1.0, 0.0), (0.0, 1.0), (1.0, 1.0), (0.0, 0.0)]
            .map(|(a, b)| pixel(a * 3f32.sqrt(), b * 3f32.sqrt()))
            .to_vec();
        let p = split(&errors);
        // Per-render MSEs: 0.5, 0.5, 1, 0. Products off the diagonal:
        // 0, 0.5, 0, 0.5, 0, 0 over the six pairs.
        assert!((p.mse.value - 0.5).abs() < 1e-6);
        assert!((p.bias2.value - 1.0 / 6.0).abs() < 1e-6);
        assert!((p.variance.value - 1.0 / 3.0).abs() < 1e-6);
        // sd of (0.5, 0.5, 1, 0) is √(1/6); over √4: √(1/24).
        assert!(
            (p.mse.se - (1.0f64 / 24.0).sqrt()).abs() < 1e-6,
            "{:?}",
            p.mse
        );
    }

    #[test]
    fn renders_without_randomness_have_no_variance_and_an_exact_bias() {
        let same = vec![vec![0.5f32, -0.25, 0.0]; 4];
        let p = split(&same);
        assert!((p.bias2.value - 0.3125 / 3.0).abs() < 1e-12);
        assert!(p.bias2.se < 1e-12 && p.variance.value.abs() < 1e-12);
    }

    /// Synthetic rows with a known bias and noise: over 2000 rows of 6
    /// seeds, the bias² averages to the known bias², and its SE agrees
    /// with the spread of the bias² from row to row (the SE's definition)
    /// and with the formula for this noise, for a bias of 0 (where the
    /// noise² term rules) and for a bias as large as the noise. The
    /// jackknife, at bias 0, overstates the variance by 2(K−1)/(K−2).
    #[test]
    fn the_bias2s_standard_error_matches_its_spread_over_many_rows() {
        let mut rng = Rng(0x5eed_1234);
        for bias in [0.0f32, 0.3] {
            let (rows, k, n, a) = (2000, 6, 300, 0.5);
            let mut values = Vec::new();
            let (mut se2, mut jack2) = (0.0, 0.0);
            for _ in 0..rows {
                let errors = renders(&mut rng, k, n, bias, a);
                let b = split(&errors).bias2;
                values.push(b.value);
                se2 += b.se * b.se / f64::from(rows);
                jack2 += jackknife(&products(&errors)).powi(2) / f64::from(rows);
            }
            let mean = values.iter().sum::<f64>() / f64::from(rows);
            let spread2 =
                values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / f64::from(rows - 1);
            let known = f64::from(bias * bias);
            let se_of_mean = (spread2 / f64::from(rows)).sqrt();
            assert!(
                (mean - known).abs() < 4.0 * se_of_mean,
                "bias {bias}: mean bias² {mean} against {known} (± {se_of_mean})"
            );
            let ratio = se2 / spread2;
            assert!(
                (0.85..1.15).contains(&ratio),
                "bias {bias}: mean SE² {se2} against the spread² {spread2}: ratio {ratio}"
            );
            if bias == 0.0 {
                let kf = k as f64;
                let jack = jack2 / spread2 / (2.0 * (kf - 1.0) / (kf - 2.0));
                assert!((0.85..1.15).contains(&jack), "jackknife: {jack}");
            }
            // And against the textbook formula for this noise: the variance
            // of the mean over n values of a U-statistic of order 2.
            let s2 = f64::from(a * a) / 3.0;
            let (kf, nf) = (k as f64, n as f64);
            let formula = (2.0 * s2 * s2 / (kf * (kf - 1.0)) + 4.0 * known * s2 / kf) / nf;
            assert!(
                (spread2 / formula - 1.0).abs() < 0.15,
                "bias {bias}: spread² {spread2}, formula {formula}"
            );
        }
    }
}
