//! Host time of one `push` + `estimate` of every generated observer (f32 tables, firmware code),
//! cycling through the design's recorded sequence. `cargo bench -p integration-tests`.

fn main() {
    divan::main();
}

macro_rules! bench_design {
    ($name:ident) => {
        #[divan::bench]
        fn $name(bencher: divan::Bencher) {
            use generated::$name as d;
            let mut observer = d::map_observer();
            let mut k = 0;
            bencher.bench_local(|| {
                k = (k + 1) % d::RECORDED_LEN;
                let _ = observer.push(
                    divan::black_box(d::RECORDED_Y[k]),
                    divan::black_box(d::RECORDED_U[k]),
                );
                divan::black_box(observer.estimate())
            });
        }
    };
}

generated::for_each_design!(bench_design);
