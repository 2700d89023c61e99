// A minimal runtime for the Arduino Uno examples (ATmega328P): USART0 output, halting, and
// the panic handler. Register access is the examples' own business (the library forbids
// unsafe code).

use core::fmt::{self, Write};

const UCSR0A: *mut u8 = 0xC0 as *mut u8;
const UCSR0B: *mut u8 = 0xC1 as *mut u8;
const UCSR0C: *mut u8 = 0xC2 as *mut u8;
const UBRR0L: *mut u8 = 0xC4 as *mut u8;
const UBRR0H: *mut u8 = 0xC5 as *mut u8;
const UDR0: *mut u8 = 0xC6 as *mut u8;

pub struct Uart;

impl Uart {
    pub fn init() -> Self {
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

/// Interrupts off and sleep: simavr ends the run ("sleeping with interrupts off").
pub fn halt() -> ! {
    // SAFETY: stopping the CPU is the intent.
    unsafe { core::arch::asm!("cli", "sleep") };
    loop {}
}

#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    let _ = Uart.write_str("PANIC\n");
    halt()
}
