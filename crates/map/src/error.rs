//! Errors caused by the input (a bad file or an invalid map). Internal bugs
//! are not reported through this type: they panic with "bug:".

use std::fmt;

/// An error caused by the input, displayed as one line:
/// `FILE: line L: what` or `FILE: triangle 17: what`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct InputError {
    /// The file the error is about, when known.
    pub file: Option<String>,
    /// Where in the file (e.g. `line 12`), when known.
    pub location: Option<String>,
    /// What is wrong, naming the element.
    pub message: String,
}

impl InputError {
    /// An error with only a message.
    pub fn new(message: impl Into<String>) -> Self {
        InputError {
            file: None,
            location: None,
            message: message.into(),
        }
    }

    /// An error at a line of a text file.
    pub fn at_line(line: usize, message: impl Into<String>) -> Self {
        InputError {
            file: None,
            location: Some(format!("line {line}")),
            message: message.into(),
        }
    }

    /// Attaches the file name (keeps an existing one).
    pub fn in_file(mut self, file: impl Into<String>) -> Self {
        if self.file.is_none() {
            self.file = Some(file.into());
        }
        self
    }
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let Some(file) = &self.file {
            write!(f, "{file}: ")?;
        }
        if let Some(loc) = &self.location {
            write!(f, "{loc}: ")?;
        }
        // one line, whatever the message contains
        write!(f, "{}", self.message.replace('\n', " "))
    }
}

impl std::error::Error for InputError {}
