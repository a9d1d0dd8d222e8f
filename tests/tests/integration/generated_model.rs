//! The model each shipped design emits as Rust, compiled here as the `generated` crate, against the
//! spec's own evaluation by exmex (the learning simulation's), and against the host's interpreter of
//! the same program (which `gen` tuned the EKF with).

use firmware::Model;
use host::plant::ModelCode;
use integration_tests::workspace_root;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// Random states in (a margin around) the design's learning box, random inputs in their ranges.
fn points(design: &host::spec::Design, count: usize) -> Vec<(Vec<f64>, Vec<f64>)> {
    let mut rng = ChaCha8Rng::seed_from_u64(99);
    (0..count)
        .map(|_| {
            let x = design
                .learning
                .axes
                .iter()
                .map(|axis| match *axis {
                    host::spec::Axis::Range { min, max, .. } => rng.random_range(min..=max),
                    // A held state still moves in a run: up to twice its value.
                    host::spec::Axis::Fixed(value) => rng.random_range(0.5 * value..=2.0 * value),
                })
                .collect();
            let u = design
                .learning
                .inputs
                .iter()
                .map(|p| rng.random_range(p.min..=p.max))
                .collect();
            (x, u)
        })
        .collect()
}

macro_rules! check_design {
    ($test:ident, $module:ident) => {
        #[test]
        fn $test() {
            use generated::$module as d;
            let design = host::spec::load(&workspace_root().join(d::SPEC)).unwrap();
            let code = ModelCode::new(&design).unwrap();
            let mut environment = Vec::new();
            let mut scratch32 = Vec::new();
            let (mut worst64, mut worst32) = (0.0_f64, 0.0_f64);
            for (x, u) in points(&design, 2000) {
                let mut f = vec![0.0; d::STATES];
                design.model.derivative(&x, &u, &mut environment, &mut f);
                let mut h = vec![0.0; d::OUTPUTS];
                design.model.outputs(&x, &u, &mut environment, &mut h);
                let r: Vec<f64> = design.targets.iter().map(|t| t.expr.eval(&environment)).collect();
                let x64: [f64; d::STATES] = std::array::from_fn(|i| x[i]);
                let u64: [f64; d::INPUTS] = std::array::from_fn(|i| u[i]);
                let (f64_, _) =
                    Model::<f64, { d::STATES }, { d::OUTPUTS }, { d::INPUTS }>::derivative(&d::Plant, &x64, &u64);
                let (h64, _) =
                    Model::<f64, { d::STATES }, { d::OUTPUTS }, { d::INPUTS }>::output(&d::Plant, &x64, &u64);
                let r64 = d::targets(&x64, &u64);
                let x32: [f32; d::STATES] = std::array::from_fn(|i| x[i] as f32);
                let u32_: [f32; d::INPUTS] = std::array::from_fn(|i| u[i] as f32);
                let (f32_, jf32) =
                    Model::<f32, { d::STATES }, { d::OUTPUTS }, { d::INPUTS }>::derivative(&d::Plant, &x32, &u32_);
                let (h32, jh32) =
                    Model::<f32, { d::STATES }, { d::OUTPUTS }, { d::INPUTS }>::output(&d::Plant, &x32, &u32_);
                let r32 = d::targets(&x32, &u32_);
                // The host's interpreter in f32 gives the emitted code's bits exactly.
                let xs: Vec<f32> = x32.to_vec();
                let us: Vec<f32> = u32_.to_vec();
                let (hf, hjf) = code.derivative(&xs, &us, &mut scratch32);
                let (hh, hjh) = code.output(&xs, &us, &mut scratch32);
                let bits = |v: &[f32]| v.iter().map(|a| a.to_bits()).collect::<Vec<_>>();
                assert_eq!(bits(&hf), bits(&f32_), "f at {x:?}");
                assert_eq!(bits(&hh), bits(&h32), "h at {x:?}");
                assert_eq!(bits(&hjf), bits(&jf32.concat()), "∂f/∂x at {x:?}");
                assert_eq!(bits(&hjh), bits(&jh32.concat()), "∂h/∂x at {x:?}");
                let truth = f.iter().chain(&h).chain(&r);
                let ours64 = f64_.iter().chain(&h64).chain(&r64);
                let ours32 = f32_.iter().chain(&h32).chain(&r32);
                for ((t, a), b) in truth.zip(ours64).zip(ours32) {
                    worst64 = worst64.max((a - t).abs() / (1.0 + t.abs()));
                    worst32 = worst32.max((f64::from(*b) - t).abs() / (1.0 + t.abs()));
                }
            }
            // f64: the same operations, libm for the platform's functions: a few ulps.
            assert!(worst64 < 1e-13, "f64: worst relative difference {worst64:e}");
            // f32: inputs rounded (2⁻²⁴ relative) and a few dozen roundings: measured worst 1.1e-6
            // (Van der Pol), 2.7e-7 (E. coli); 1e-5 leaves a factor 10. A wrong operation or a
            // dropped term is off by O(1).
            assert!(worst32 < 1e-5, "f32: worst relative difference {worst32:e}");
        }
    };
}

check_design!(vanderpol_model_is_the_specs, vanderpol);
check_design!(ecoli_x0_0p5_model_is_the_specs, ecoli_x0_0p5);
check_design!(ecoli_x0_2_model_is_the_specs, ecoli_x0_2);
check_design!(two_tanks_model_is_the_specs, two_tanks);

/// Each design's written-out EKF (`Ekf`, what the chip runs) against the library filter it writes out
/// (`reference_ekf`: `firmware::Ekf` over `firmware::Rk4` of the emitted `Plant`, same constants) over
/// the recorded sequence with every fifth measurement refused. The same operations in the same order,
/// only `0·a`, `1·a`, `0 + a` left out (exact for finite values): the same bits, in f64 and in f32,
/// refusals included.
macro_rules! check_filter {
    ($test:ident, $module:ident) => {
        check_filter!($test, generated::$module);
    };
    ($test:ident, $path:path) => {
        #[test]
        fn $test() {
            use $path as d;
            fn run<T: firmware::Scalar + firmware::emitted::Maths + std::fmt::Debug>(
                exact: impl Fn(f32) -> T,
                bits: impl Fn(T) -> u64,
            ) {
                let mut written = d::Ekf::<T>::new();
                let mut library = d::reference_ekf::<T>();
                for (k, (y, u)) in d::RECORDED_Y.iter().zip(&d::RECORDED_U).enumerate() {
                    let mut y = y.map(&exact);
                    if k % 5 == 3 {
                        y[0] = T::literal(f32::NAN, f64::NAN);
                    }
                    let u = u.map(&exact);
                    let (a, b) = (written.push(&y, &u), library.push(&y, &u));
                    let all = |e: Result<[T; d::STATES], firmware::rules::Refused>,
                               x: [T; d::STATES],
                               p: [[T; d::STATES]; d::STATES]| {
                        e.into_iter()
                            .flatten()
                            .chain(x)
                            .chain(p.into_iter().flatten())
                            .map(&bits)
                            .collect::<Vec<u64>>()
                    };
                    assert_eq!(
                        all(a, written.state(), written.covariance()),
                        all(b, library.state(), library.covariance()),
                        "sample {k}: written-out {a:?}, library {b:?}"
                    );
                }
            }
            run::<f64>(f64::from, f64::to_bits);
            run::<f32>(|v| v, |v| u64::from(v.to_bits()));
        }
    };
}

check_filter!(vanderpol_filter_is_the_librarys, vanderpol);
check_filter!(ecoli_x0_0p5_filter_is_the_librarys, ecoli_x0_0p5);
check_filter!(ecoli_x0_2_filter_is_the_librarys, ecoli_x0_2);
check_filter!(two_tanks_filter_is_the_librarys, two_tanks);

check_filter!(a_fixed_full_q_and_p0_filter_is_the_librarys, crate::vanderpol_beta7);

#[test]
fn the_fixtures_filter_carries_the_constants_its_spec_fixes() {
    use crate::vanderpol_beta7 as d;
    // Written by hand from tests/fixtures/vanderpol_beta7.toml, `[observer.ekf]`.
    assert_eq!(d::EKF_Q, [[3.0e-5, 1.0e-5], [1.0e-5, 2.0e-3]]);
    let ekf = d::ekf();
    assert_eq!(ekf.state(), [1.0, 0.7]);
    assert_eq!(ekf.covariance(), [[0.2, 0.05], [0.05, 0.5]]);
    // `[observer.ukf]` fixes P(0) alone, a diagonal; its Q is tuned (a diagonal).
    assert_eq!(d::ukf().covariance(), [[0.2, 0.0], [0.0, 0.5]]);
    assert_eq!(d::UKF_Q.len(), 2);
}
