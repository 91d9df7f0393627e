//! Errors a user can act on: each names the field or file and the offending value, on one
//! line (control characters in values are shown escaped).

use std::path::PathBuf;

use crate::text::one_line;

pub type Result<T, E = Error> = std::result::Result<T, E>;

#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// Bad input: a scenario field, a CLI value, a plan file. Exit code 2.
    #[error("{}: {}", one_line(field), one_line(message))]
    Input { field: String, message: String },
    /// A file could not be read or written. Exit code 2.
    #[error("{}: {}", one_line(&path.display().to_string()), one_line(&source.to_string()))]
    Io {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
}

impl Error {
    /// Shorthand for an input error naming `field`.
    pub fn input(field: impl Into<String>, message: impl Into<String>) -> Self {
        Error::Input { field: field.into(), message: message.into() }
    }

    /// The same error, naming `field` instead (e.g. a CLI flag for a scenario field).
    pub fn for_field(self, field: impl Into<String>) -> Self {
        match self {
            Error::Input { message, .. } => Error::Input { field: field.into(), message },
            other => other,
        }
    }

    pub fn io(path: impl Into<PathBuf>, source: std::io::Error) -> Self {
        Error::Io { path: path.into(), source }
    }
}
