//! Shader numerics, measured: generated hard-case inputs, the f64 reference of each formulation
//! the library offers, the error statistics (relative error, ULPs, NaN/Inf), and (with the `gpu`
//! feature) a harness that runs the compiled library functions on a real adapter.

#[cfg(feature = "gpu")]
pub mod gpu;
#[cfg(feature = "gpu")]
pub mod plot;

use crate::reference::{self as r, Brdf, Light, Surface};
use std::fmt::Write as _;

/// A way the library computes the specular term, chosen by keyword.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Formulation {
    /// The seed's minimal Cook-Torrance exactly as written.
    Seed,
    /// `_SPECULAR_STABLE`: the same model without cancellation, roughness floored.
    Stable,
    /// `_SPECULAR_HALF`: the stable form in f16 arithmetic (adapters with `shader-f16`).
    Half,
    /// `_SPECULAR_RATIO`: the stable form's model as a ratio of squares of L + V (no
    /// normalised half vector, no cancellation).
    Ratio,
}

impl Formulation {
    /// Every formulation, in report order.
    pub const ALL: [Formulation; 4] =
        [Formulation::Seed, Formulation::Stable, Formulation::Half, Formulation::Ratio];

    /// Its name in the report.
    pub fn name(self) -> &'static str {
        match self {
            Formulation::Seed => "seed",
            Formulation::Stable => "stable",
            Formulation::Half => "stable f16",
            Formulation::Ratio => "ratio",
        }
    }

    /// The keywords that select it.
    pub fn keywords(self) -> &'static [&'static str] {
        match self {
            Formulation::Seed => &[],
            Formulation::Stable => &["_SPECULAR_STABLE"],
            Formulation::Half => &["_SPECULAR_HALF"],
            Formulation::Ratio => &["_SPECULAR_RATIO"],
        }
    }

    /// Needs `shader-f16` (naga's `SHADER_FLOAT16`, wgpu's `SHADER_F16`).
    pub fn needs_f16(self) -> bool {
        self == Formulation::Half
    }
}

/// One evaluation: a surface lit by one light.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Case {
    /// The surface.
    pub surface: Surface,
    /// The light.
    pub light: Light,
    /// Whether alpha is applied to diffuse.
    pub premultiply: bool,
}

/// A generated set of hard cases.
#[derive(Debug, Clone)]
pub struct CaseSet {
    /// The set's name in the report.
    pub name: String,
    /// Its cases.
    pub cases: Vec<Case>,
    /// For the light-count set: lights in `_CustomLight` and the count to upload per case.
    pub lights: Option<(Vec<Light>, Vec<i32>)>,
}

/// Rounds to what an f32 input holds, so that input rounding is not counted as error.
fn f32_exact(x: f64) -> f64 {
    f64::from(x as f32)
}

fn round_case(case: Case) -> Case {
    let v = |v: r::Vec3| v.map(f32_exact);
    let s = case.surface;
    Case {
        surface: Surface {
            normal: v(s.normal),
            view_direction: v(s.view_direction),
            color: v(s.color),
            alpha: f32_exact(s.alpha),
            metallic: f32_exact(s.metallic),
            smoothness: f32_exact(s.smoothness),
        },
        light: Light { color: v(case.light.color), direction: v(case.light.direction) },
        premultiply: case.premultiply,
    }
}

/// A deterministic generator (xorshift), so the sets are the same on every machine.
struct Random(u64);

impl Random {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    fn direction(&mut self) -> r::Vec3 {
        loop {
            let v = [self.next() * 2.0 - 1.0, self.next() * 2.0 - 1.0, self.next() * 2.0 - 1.0];
            let len = r::dot(v, v).sqrt();
            if len > 0.1 && len <= 1.0 {
                return r::scale(v, 1.0 / len);
            }
        }
    }

    /// A surface facing up (normal (0, 1, 0)) under a white light, the light's and the view's
    /// directions above it, smoothness and (unless given) metallic random; drawn in that order.
    fn facing_up(&mut self, metallic: Option<f64>) -> Case {
        let light = Light { color: WHITE, direction: self.upper_direction() };
        let view = self.upper_direction();
        let smoothness = self.next();
        let metallic = metallic.unwrap_or_else(|| self.next());
        Case { surface: surface([0.0, 1.0, 0.0], view, smoothness, metallic), light, premultiply: false }
    }

    /// A direction above the surface (y > 0).
    fn upper_direction(&mut self) -> r::Vec3 {
        let d = self.direction();
        let up = [d[0], d[1].abs().max(0.05), d[2]];
        r::normalize(up)
    }
}

fn surface(normal: r::Vec3, view: r::Vec3, smoothness: f64, metallic: f64) -> Surface {
    Surface { normal, view_direction: view, color: [0.9, 0.6, 0.3], alpha: 1.0, metallic, smoothness }
}

const WHITE: r::Vec3 = [1.0, 1.0, 1.0];

/// Samples per hard-case set in the tests and the timing runs; `kiln accuracy` measures
/// [`REPORT_SAMPLES`].
pub const TEST_SAMPLES: usize = 64;
/// Samples per hard-case set `kiln accuracy` measures by default.
pub const REPORT_SAMPLES: usize = 1_000_000;

/// How many hard-case sets there are ([`hard_case_set`] indices).
pub const HARD_CASE_SETS: usize = 12;

/// The smoothness of each n·h → 1 set.
const MIRROR_SMOOTHNESS: [f64; 5] = [0.9, 0.95, 0.99, 0.999, 1.0];

/// Every hard-case set with `samples` cases each (see [`hard_case_set`]).
pub fn hard_cases(samples: usize) -> Vec<CaseSet> {
    (0..HARD_CASE_SETS).map(|index| hard_case_set(index, samples)).collect()
}

/// Hard-case set `index` (below [`HARD_CASE_SETS`]) with `samples` cases, generated, never
/// hand-picked: the same cases on every machine, each set from its own seed so that one set
/// can be made without the others. Sweeps (n·h → 1, grazing angles, light colours) cover their
/// range evenly on a log scale whatever the sample count; directions the sweep leaves free are
/// random.
pub fn hard_case_set(index: usize, samples: usize) -> CaseSet {
    let mut random = Random(0x9e37_79b9_7f4a_7c15 ^ (index as u64 + 1).wrapping_mul(0x2545_f491_4f6c_dd1d));
    let n = samples.max(2);
    // Position k of n along a sweep, 0 to 1.
    let along = |k: usize| k as f64 / (n - 1) as f64;
    let set = |name: String, cases: Vec<Case>| CaseSet {
        name,
        cases: cases.into_iter().map(round_case).collect(),
        lights: None,
    };
    let up = [0.0, 1.0, 0.0];
    match index {
        // n.h -> 1: the light approaches the mirror direction of the view, from 1 to 1e-7 radians,
        // in a plane through the normal at a random azimuth, the view 0.1 to 0.55 radians from the
        // normal (so the light stays above the horizon).
        0..=4 => {
            let smoothness = MIRROR_SMOOTHNESS[index];
            let cases = (0..n)
                .map(|k| {
                    let a = 0.1 + 0.45 * random.next();
                    let azimuth = std::f64::consts::TAU * random.next();
                    let (sin, cos) = azimuth.sin_cos();
                    let turn = |v: r::Vec3| [v[0] * cos, v[1], v[0] * sin];
                    let b = a + 10f64.powf(-7.0 * along(k));
                    let view = turn([a.sin(), a.cos(), 0.0]);
                    let light = Light { color: WHITE, direction: turn([-b.sin(), b.cos(), 0.0]) };
                    Case { surface: surface(up, view, smoothness, 0.0), light, premultiply: false }
                })
                .collect();
            set(format!("n.h -> 1, smoothness {smoothness}"), cases)
        }
        // L = -V: the half vector is zero.
        5 => {
            let cases = (0..n)
                .map(|_| {
                    let view = random.direction();
                    let light = Light { color: WHITE, direction: r::scale(view, -1.0) };
                    Case {
                        surface: surface(random.direction(), view, random.next(), random.next()),
                        light,
                        premultiply: false,
                    }
                })
                .collect();
            set("L = -V".into(), cases)
        }
        // Zero-length and denormal normals.
        6 => {
            let normals: [r::Vec3; 6] = [
                [0.0; 3],
                [1e-40, 0.0, 0.0],
                [0.0, 1e-39, 0.0],
                [1e-20, 1e-20, 0.0],
                [0.0, 1e-45, 0.0],
                [1e-38, 1e-38, 1e-38],
            ];
            let cases = (0..n)
                .map(|k| {
                    let view = random.upper_direction();
                    let light = Light { color: WHITE, direction: random.upper_direction() };
                    Case {
                        surface: surface(normals[k % normals.len()], view, 0.5, 0.0),
                        light,
                        premultiply: false,
                    }
                })
                .collect();
            set("zero and denormal normals".into(), cases)
        }
        // Grazing n.l and n.v: elevations from 0.1 down to 1e-7 radians, at random azimuths.
        7 => {
            let cases = (0..n)
                .map(|k| {
                    let e = 10f64.powf(-1.0 - 6.0 * along(k));
                    let azimuth = std::f64::consts::TAU * random.next();
                    let (sin, cos) = azimuth.sin_cos();
                    let light = Light { color: WHITE, direction: [e.cos() * cos, e.sin(), e.cos() * sin] };
                    let view = [-(e * 0.5).cos() * 0.6, (e * 0.5).sin(), (e * 0.5).cos() * 0.8];
                    Case { surface: surface(up, r::normalize(view), 0.8, 0.5), light, premultiply: false }
                })
                .collect();
            set("grazing n.l and n.v".into(), cases)
        }
        // HDR light colours from 1e-6 to 1e5.
        8 => {
            let cases = (0..n)
                .map(|k| {
                    let intensity = 10f64.powf(-6.0 + 11.0 * along(k));
                    let mut case = random.facing_up(None);
                    case.light.color = [intensity, intensity * 0.5, intensity * 0.25];
                    case
                })
                .collect();
            set("light colours 1e-6 to 1e5".into(), cases)
        }
        // Metallic 0 and 1.
        9 => {
            let cases = (0..n).map(|k| random.facing_up(Some((k % 2) as f64))).collect();
            set("metallic 0 and 1".into(), cases)
        }
        // Alpha 0, premultiplied.
        10 => {
            let cases = (0..n)
                .map(|_| {
                    let mut case = random.facing_up(None);
                    case.surface.alpha = 0.0;
                    Case { premultiply: true, ..case }
                })
                .collect();
            set("alpha 0 with premultiply".into(), cases)
        }
        // Light counts 0 to 5 (one above the maximum) through `GetLighting` and `_CustomLight`,
        // each count for a sixth of the cases.
        _ => {
            let lights: Vec<Light> = (0..4)
                .map(|i| Light {
                    color: [1.0, 0.8 - 0.1 * i as f64, 0.5],
                    direction: random.upper_direction(),
                })
                .map(|l| Light { color: l.color.map(f32_exact), direction: l.direction.map(f32_exact) })
                .collect();
            let counts: Vec<i32> = (0..n).map(|k| (k % 6) as i32).collect();
            let cases = counts
                .iter()
                .map(|_| Case {
                    surface: surface(up, random.upper_direction(), 0.7, 0.3),
                    light: lights[0],
                    premultiply: false,
                })
                .map(round_case)
                .collect();
            CaseSet { name: "light counts 0 to 5".into(), cases, lights: Some((lights, counts)) }
        }
    }
}

/// The f64 reference of what a formulation computes for one case (lit colour of one light).
pub fn reference(case: &Case, formulation: Formulation) -> r::Vec3 {
    let brdf: Brdf = r::get_brdf(&case.surface, case.premultiply);
    let specular = match formulation {
        Formulation::Seed => r::specular_strength(&case.surface, &brdf, &case.light),
        // The f16 and ratio forms compute the stable form's model; their error is their arithmetic's.
        Formulation::Stable | Formulation::Half | Formulation::Ratio => {
            r::specular_strength_stable(&case.surface, &brdf, &case.light)
        }
    };
    let direct = r::add(r::scale(brdf.specular, specular), brdf.diffuse);
    r::mul(r::incoming_light(&case.surface, &case.light), direct)
}

/// The reference of the light-count set: `GetLighting` over the first `count` lights (at most 4).
pub fn reference_lights(case: &Case, lights: &[Light], count: i32, formulation: Formulation) -> r::Vec3 {
    let used = lights.iter().take(count.clamp(0, r::MAX_DIRECTIONAL_LIGHT_COUNT as i32) as usize);
    used.fold([0.0; 3], |sum, light| r::add(sum, reference(&Case { light: *light, ..*case }, formulation)))
}

/// Results smaller than this are compared absolutely: f32 denormals (below 1.2e-38) are flushed to
/// zero by GPUs, which is not an error of the formula.
pub const ABSOLUTE_FLOOR: f64 = 1e-30;

/// Error statistics of one formulation on one set.
#[derive(Debug, Clone, PartialEq)]
pub struct Stats {
    /// Cases measured.
    pub cases: usize,
    /// Normwise relative error: max over components of |gpu - ref| / max(|ref|, 1e-30), over cases.
    pub max_relative: f64,
    /// Mean relative error.
    pub mean_relative: f64,
    /// Distance in units in the last place between the GPU's f32 and the reference rounded to f32.
    pub max_ulps: u64,
    /// Results that were NaN or infinite.
    pub nan_or_inf: usize,
}

fn ulps(a: f32, b: f32) -> u64 {
    let key = |x: f32| {
        let bits = x.to_bits() as i64;
        if bits < 0 { i64::from(i32::MIN) - bits } else { bits }
    };
    if a == b { 0 } else { (key(a) - key(b)).unsigned_abs() }
}

/// Compares GPU results with references.
pub fn stats(gpu: &[[f32; 3]], references: &[r::Vec3]) -> Stats {
    let mut stats =
        Stats { cases: gpu.len(), max_relative: 0.0, mean_relative: 0.0, max_ulps: 0, nan_or_inf: 0 };
    let mut sum = 0.0;
    for (g, want) in gpu.iter().zip(references) {
        if g.iter().any(|x| !x.is_finite()) {
            stats.nan_or_inf += 1;
            continue;
        }
        let relative = case_error(*g, *want);
        stats.max_relative = stats.max_relative.max(relative);
        sum += relative;
        for k in 0..3 {
            stats.max_ulps = stats.max_ulps.max(ulps(g[k], want[k] as f32));
        }
    }
    let finite = stats.cases - stats.nan_or_inf;
    stats.mean_relative = if finite > 0 { sum / finite as f64 } else { 0.0 };
    stats
}

/// One line of the speed-against-error table.
#[derive(Debug, Clone)]
pub struct Row {
    /// The formulation's name.
    pub formulation: &'static str,
    /// The case set's name.
    pub set: String,
    /// Its error statistics.
    pub stats: Stats,
}

/// A timing of one kernel.
#[derive(Debug, Clone)]
pub struct Timing {
    /// What was timed.
    pub what: String,
    /// GPU time per evaluation.
    pub nanoseconds_per_evaluation: f64,
}

/// The report `kiln accuracy` prints.
pub fn render(adapter: &str, rows: &[Row], timings: &[Timing], method: &str) -> String {
    let mut out = format!("adapter: {adapter}\n\n");
    let _ = writeln!(
        out,
        "{:<10} {:<30} {:>5} {:>12} {:>12} {:>10} {:>8}",
        "formula", "hard cases", "n", "max rel", "mean rel", "max ulp", "NaN/Inf"
    );
    for row in rows {
        let s = &row.stats;
        let _ = writeln!(
            out,
            "{:<10} {:<30} {:>5} {:>12.3e} {:>12.3e} {:>10} {:>8}",
            row.formulation, row.set, s.cases, s.max_relative, s.mean_relative, s.max_ulps, s.nan_or_inf
        );
    }
    let _ = writeln!(out, "\n{:<58} {:>12}", "GPU time per evaluation", "ns");
    for timing in timings {
        let _ = writeln!(out, "{:<58} {:>12.4}", timing.what, timing.nanoseconds_per_evaluation);
    }
    let _ = writeln!(out, "\n{method}");
    out
}

/// One case's error as [`stats`] measures it: normwise relative, compared absolutely below
/// [`ABSOLUTE_FLOOR`] (GPUs flush denormals); NaN or Inf is infinitely wrong.
pub fn case_error(gpu: [f32; 3], want: r::Vec3) -> f64 {
    if gpu.iter().any(|x| !x.is_finite()) {
        return f64::INFINITY;
    }
    let scale = want.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let difference = (0..3).fold(0.0f64, |m, k| m.max((f64::from(gpu[k]) - want[k]).abs()));
    difference / scale.max(ABSOLUTE_FLOOR)
}

/// Below this N·L a lit colour's relative error is N·L's own f32 rounding (about 1e-7 absolute,
/// so 1e-5 relative at N·L = 0.01 and anything nearer 0) whatever the BRDF's formula: the
/// statistics and the search leave such cases out unless N·L is exact ([`counted`]).
pub const MIN_N_DOT_L: f64 = 0.05;

/// Whether a case's error is counted: N·L is at least [`MIN_N_DOT_L`], or exact in f32 because
/// the normal lies on a coordinate axis (the grazing set's normal is (0, 1, 0), so its N·L down
/// to 1e-7 is measured).
pub fn counted(case: &Case) -> bool {
    let on_axis = case.surface.normal.iter().filter(|&&c| c == 0.0).count() >= 2;
    on_axis || r::dot(case.surface.normal, case.light.direction) >= MIN_N_DOT_L
}

/// [`case_error`] where the case is [`counted`], else 0.
fn search_error(gpu: [f32; 3], case: &Case, formulation: Formulation) -> f64 {
    if !counted(case) {
        return 0.0;
    }
    case_error(gpu, reference(case, formulation))
}

/// The worst input a search found, with its error.
#[derive(Debug, Clone, Copy)]
pub struct Found {
    /// The input.
    pub case: Case,
    /// Its error ([`case_error`]).
    pub error: f64,
    /// Evaluations the search made.
    pub evaluations: usize,
}

/// Cases per evaluation round of [`search`], and rounds.
pub const SEARCH_BATCH: usize = 4096;
/// Rounds of [`search`]: a quarter of each round random restarts, the rest the best inputs so
/// far moved by 10^-1 to 10^-7 (directions in radians), so a search can close in on a worst case
/// as narrow as the seed's n·h → 1.
pub const SEARCH_ROUNDS: usize = 24;
const SEARCH_ELITES: usize = 32;

impl Random {
    /// Any input: three directions over the sphere, smoothness, metallic and colour in [0, 1].
    fn case(&mut self) -> Case {
        let surface = Surface {
            normal: self.direction(),
            view_direction: self.direction(),
            color: [self.next(), self.next(), self.next()],
            alpha: 1.0,
            metallic: self.next(),
            smoothness: self.next(),
        };
        Case { surface, light: Light { color: WHITE, direction: self.direction() }, premultiply: false }
    }

    /// `case` moved by about `scale`: each direction turned by up to `scale` radians, each scalar
    /// moved by up to `scale` (kept in [0, 1]).
    fn nearby(&mut self, case: &Case, scale: f64) -> Case {
        let mut turn = |v: r::Vec3| {
            let moved = r::add(v, r::scale(self.direction(), scale * self.next()));
            r::normalize(moved)
        };
        let (normal, view, light) =
            (turn(case.surface.normal), turn(case.surface.view_direction), turn(case.light.direction));
        let mut near = |x: f64| (x + scale * (self.next() * 2.0 - 1.0)).clamp(0.0, 1.0);
        let s = case.surface;
        let surface = Surface {
            normal,
            view_direction: view,
            color: [near(s.color[0]), near(s.color[1]), near(s.color[2])],
            metallic: near(s.metallic),
            smoothness: near(s.smoothness),
            ..s
        };
        Case { surface, light: Light { direction: light, ..case.light }, ..*case }
    }
}

/// Searches the whole input space for the input where `evaluate` (a formulation run on an
/// adapter, cases in, colours out) is worst against `formulation`'s f64 reference (relative
/// error over the [`counted`] cases): random restarts plus local
/// search around the worst inputs so far, at scales from 10^-1 to 10^-7. Deterministic for a
/// given `evaluate`.
pub fn search(formulation: Formulation, evaluate: &mut dyn FnMut(&[Case]) -> Vec<[f32; 3]>) -> Found {
    let mut random = Random(0x2545_f491_4f6c_dd1d);
    let mut elites: Vec<(f64, Case)> = Vec::new();
    let mut evaluations = 0;
    for _ in 0..SEARCH_ROUNDS {
        let batch: Vec<Case> = (0..SEARCH_BATCH)
            .map(|i| match elites.get(i % SEARCH_ELITES.max(1)) {
                Some((_, elite)) if i >= SEARCH_BATCH / 4 => {
                    let scale = 10f64.powi(-1 - (random.next() * 7.0) as i32);
                    random.nearby(elite, scale)
                }
                _ => random.case(),
            })
            .map(round_case)
            .collect();
        let results = evaluate(&batch);
        evaluations += batch.len();
        for (case, result) in batch.into_iter().zip(results) {
            let error = search_error(result, &case, formulation);
            elites.push((if error.is_nan() { f64::INFINITY } else { error }, case));
        }
        elites.sort_by(|a, b| b.0.total_cmp(&a.0));
        elites.truncate(SEARCH_ELITES);
    }
    let (error, case) = elites[0];
    Found { case, error, evaluations }
}

/// The worst inputs found, as a table.
pub fn render_search(found: &[(Formulation, Found)]) -> String {
    let mut out = format!(
        "\nWorst found by search ({SEARCH_ROUNDS} rounds of {SEARCH_BATCH} inputs per formulation, N.L >= {MIN_N_DOT_L})\n{:<11}{:>11}  input\n",
        "formula", "max rel"
    );
    for (formulation, found) in found {
        let c = &found.case;
        let v = |v: r::Vec3| format!("({:.6}, {:.6}, {:.6})", v[0], v[1], v[2]);
        let _ = writeln!(
            out,
            "{:<11}{:>11.3e}  N {} V {} L {} smoothness {:.6} metallic {:.4} colour {}",
            formulation.name(),
            found.error,
            v(c.surface.normal),
            v(c.surface.view_direction),
            v(c.light.direction),
            c.surface.smoothness,
            c.surface.metallic,
            v(c.surface.color)
        );
    }
    out
}
