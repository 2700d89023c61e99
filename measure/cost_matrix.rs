//! What the keyboard matrix costs on a Cortex-M: `scripts/cost-report.sh` runs this under QEMU
//! with an instruction trace and counts the instructions between calls of `cost_mark`: a 100-key
//! `LearningMatrix` typed on and idle, against debouncr and a QMK-like `sym_eager_pk` on the same
//! scans (`common/matrix_cost.rs`). On the host it does nothing.
#![cfg_attr(target_os = "none", no_std, no_main)]

#[cfg(target_os = "none")]
#[path = "common/matrix_cost.rs"]
mod matrix;

#[cfg(target_os = "none")]
mod firmware {
    use core::hint::black_box;
    use cortex_m as _;
    use cortex_m_semihosting::debug;
    use panic_halt as _;

    use contact_bounce::debounce::matrix::LearningMatrix;
    use core::mem::size_of;

    // What each matrix keeps in RAM, as symbols whose size the report reads (`llvm-nm -S`): ours
    // (10 x 10 keys in u16 rows), the model alone (a matrix with no keys), debouncr's 100 keys
    // and the QMK-like debouncer.
    #[used]
    #[no_mangle]
    static RAM_MATRIX: [u8; size_of::<LearningMatrix<u16, 10, 10>>()] =
        [0; size_of::<LearningMatrix<u16, 10, 10>>()];
    #[used]
    #[no_mangle]
    static RAM_MODEL: [u8; size_of::<LearningMatrix<u16, 0, 0>>()] =
        [0; size_of::<LearningMatrix<u16, 0, 0>>()];
    #[used]
    #[no_mangle]
    static RAM_DEBOUNCR: [u8; size_of::<[debouncr::Debouncer<u8, debouncr::Repeat5>; 100]>()] =
        [0; size_of::<[debouncr::Debouncer<u8, debouncr::Repeat5>; 100]>()];
    #[used]
    #[no_mangle]
    static RAM_QMK: [u8; size_of::<super::matrix::QmkEager>()] =
        [0; size_of::<super::matrix::QmkEager>()];

    /// The marker: the instructions between two calls are one measurement.
    #[inline(never)]
    #[no_mangle]
    pub extern "C" fn cost_mark(id: u32) {
        black_box(id);
    }

    #[cortex_m_rt::entry]
    fn main() -> ! {
        super::matrix::run_matrix(|id| cost_mark(u32::from(id)), 0);
        debug::exit(debug::EXIT_SUCCESS);
        loop {
            cortex_m::asm::wfi();
        }
    }
}

#[cfg(not(target_os = "none"))]
fn main() {}
