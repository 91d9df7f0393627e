//! Errors a user can act on: each names the field or file and the offending value.

use std::path::PathBuf;

pub type Result<T, E = Error> = std::result::Result<T, E>;

#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// Bad input: a scenario field, a CLI value, a plan file. Exit code 2.
    #[error("{field}: {message}")]
    Input { field: String, message: String },
    /// A file could not be read or written. Exit code 2.
    #[error("{}: {source}", path.display())]
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
