//! Predictions on an Arduino Uno (ATmega328P), printed over the UART: the map tier for two
//! switches of physics.md sec. 7 and a compile-time window (`common/uno_report.rs`).
//!
//! Build with the nightly toolchain for `avr-none` (`scripts/uno.sh` does it and runs it in
//! simavr); on the host it prints the same lines, which is what CI compares.
#![cfg_attr(target_arch = "avr", no_std, no_main, feature(asm_experimental_arch))]

#[path = "common/uno_report.rs"]
mod report;

#[cfg(target_arch = "avr")]
mod firmware {
    use core::fmt::{self, Write};

    // ATmega328P USART0 registers (data space addresses).
    const UCSR0A: *mut u8 = 0xC0 as *mut u8;
    const UCSR0B: *mut u8 = 0xC1 as *mut u8;
    const UCSR0C: *mut u8 = 0xC2 as *mut u8;
    const UBRR0L: *mut u8 = 0xC4 as *mut u8;
    const UBRR0H: *mut u8 = 0xC5 as *mut u8;
    const UDR0: *mut u8 = 0xC6 as *mut u8;

    struct Uart;

    impl Uart {
        fn init() -> Self {
            // 9600 baud at 16 MHz (UBRR = 103), 8N1, transmitter on.
            // SAFETY: fixed, valid I/O register addresses of the ATmega328P.
            unsafe {
                UBRR0H.write_volatile(0);
                UBRR0L.write_volatile(103);
                UCSR0C.write_volatile(0b0000_0110);
                UCSR0B.write_volatile(1 << 3);
            }
            Self
        }
        fn byte(&mut self, b: u8) {
            // SAFETY: as above; wait for an empty data register, then write it.
            unsafe {
                while UCSR0A.read_volatile() & (1 << 5) == 0 {}
                UDR0.write_volatile(b);
            }
        }
    }

    impl Write for Uart {
        fn write_str(&mut self, s: &str) -> fmt::Result {
            s.bytes().for_each(|b| self.byte(b));
            Ok(())
        }
    }

    fn halt() -> ! {
        // Interrupts off and sleep: simavr ends the run ("sleeping with interrupts off").
        // SAFETY: stopping the CPU is the intent.
        unsafe { core::arch::asm!("cli", "sleep") };
        loop {}
    }

    #[no_mangle]
    pub extern "C" fn main() -> ! {
        let mut uart = Uart::init();
        if super::report::run(&mut uart).is_err() {
            let _ = uart.write_str("report failed\n");
        }
        let _ = uart.write_str("done\n");
        halt()
    }

    #[panic_handler]
    fn panic(_: &core::panic::PanicInfo) -> ! {
        let _ = Uart.write_str("PANIC\n");
        halt()
    }
}

#[cfg(not(target_arch = "avr"))]
fn main() {
    let mut out = String::new();
    if report::run(&mut out).is_err() {
        std::process::exit(1);
    }
    println!("{out}done");
}
