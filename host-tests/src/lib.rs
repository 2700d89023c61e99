//! Host-side checks of `contact-bounce`.
