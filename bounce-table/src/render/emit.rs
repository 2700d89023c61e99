//! Generated code, C or Rust: the one emitter of the table mode's `--format c|rust` and of
//! `calibrate --format c|rust`. A C file is a header with an include guard and `#define`s; a
//! Rust file has plain `//` comments (not inner doc comments, so it can be `include!`d) and
//! `pub const`s. Text from a file (a switch's name, a path) goes through
//! [`crate::render::output::comment`] first: no newline or `*/` can end a comment early.

/// The language of a generated file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Lang {
    /// A C header.
    C,
    /// Rust constants.
    Rust,
}

impl Lang {
    /// A file-level comment line.
    #[must_use]
    pub fn comment(self, text: &str) -> String {
        match self {
            Self::C => format!("/* {text} */\n"),
            Self::Rust => format!("// {text}\n"),
        }
    }

    /// A comment on the constant that follows it.
    #[must_use]
    pub fn doc(self, text: &str) -> String {
        match self {
            Self::C => format!("/* {text} */\n"),
            Self::Rust => format!("/// {text}\n"),
        }
    }

    /// The start of the file's body (C: the include guard).
    #[must_use]
    pub fn open(self, guard: &str) -> String {
        match self {
            Self::C => format!("#ifndef {guard}\n#define {guard}\n"),
            Self::Rust => String::new(),
        }
    }

    /// The end of the file (C: the include guard's end).
    #[must_use]
    pub fn close(self, guard: &str) -> String {
        match self {
            Self::C => format!("#endif /* {guard} */\n"),
            Self::Rust => String::new(),
        }
    }

    /// A 32-bit unsigned constant.
    #[must_use]
    pub fn u32(self, id: &str, value: u32) -> String {
        match self {
            Self::C => format!("#define {id} {value}u\n"),
            Self::Rust => format!("pub const {id}: u32 = {value};\n"),
        }
    }

    /// A 64-bit unsigned constant.
    #[must_use]
    pub fn u64(self, id: &str, value: u64) -> String {
        match self {
            Self::C => format!("#define {id} {value}ull\n"),
            Self::Rust => format!("pub const {id}: u64 = {value};\n"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Lang;

    #[test]
    fn constants_comments_and_guards_in_both_languages() {
        assert_eq!(Lang::C.u32("W", 3), "#define W 3u\n");
        assert_eq!(Lang::C.u64("W", 3), "#define W 3ull\n");
        assert_eq!(Lang::Rust.u32("W", 3), "pub const W: u32 = 3;\n");
        assert_eq!(Lang::Rust.u64("W", 3), "pub const W: u64 = 3;\n");
        assert_eq!(Lang::C.comment("x"), "/* x */\n");
        // Rust: plain comments at file level (the file can be `include!`d), doc comments on
        // constants.
        assert_eq!(Lang::Rust.comment("x"), "// x\n");
        assert_eq!(Lang::Rust.doc("x"), "/// x\n");
        assert_eq!(
            Lang::C.open("G") + &Lang::C.close("G"),
            "#ifndef G\n#define G\n#endif /* G */\n"
        );
        assert!(Lang::Rust.open("G").is_empty() && Lang::Rust.close("G").is_empty());
    }
}
