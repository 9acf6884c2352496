//! Writing files so that nothing is lost: every file is written to a
//! temporary sibling, flushed to disk and renamed into place. A [`FileSet`]
//! writes several files together: all of them are staged first, so a failure
//! while writing (a full disk, a read-only folder) leaves the folder as it
//! was, with no temporary file behind; only the final renames can leave a
//! partial set, and the error then names what was and was not written.

use std::fmt;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

/// Why a file (or a set of files) could not be written.
#[derive(Debug)]
pub struct WriteError {
    /// The file that failed.
    pub path: PathBuf,
    /// What the operating system said.
    pub cause: std::io::Error,
    /// Files of the same set that were written before the failure.
    pub written: Vec<PathBuf>,
    /// Files of the same set that were not written (the failed one first).
    pub not_written: Vec<PathBuf>,
}

impl fmt::Display for WriteError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "cannot write {}: {}", self.path.display(), self.cause)?;
        let names = |files: &[PathBuf]| files.iter().map(|p| p.display().to_string()).collect::<Vec<_>>().join(", ");
        if !self.written.is_empty() {
            write!(f, " (written: {}; not written: {})", names(&self.written), names(&self.not_written))?;
        } else if self.not_written.len() > 1 {
            write!(
                f,
                " (none of the {} files was written; files already there are unchanged)",
                self.not_written.len()
            )?;
        }
        Ok(())
    }
}

impl std::error::Error for WriteError {}

/// Distinguishes temporaries of concurrent writes to the same name.
static SERIAL: AtomicUsize = AtomicUsize::new(0);

/// Files written together. [`FileSet::stage`] writes each to a temporary
/// sibling; [`FileSet::commit`] renames them all into place. Temporaries not
/// committed are removed when the set is dropped, so an error while staging
/// leaves nothing behind and changes no existing file.
#[derive(Debug, Default)]
pub struct FileSet {
    /// (temporary, final path) of every staged file, in staging order.
    staged: Vec<(PathBuf, PathBuf)>,
}

impl FileSet {
    /// An empty set.
    pub fn new() -> FileSet {
        FileSet::default()
    }

    /// Writes `bytes` to a temporary sibling of `path`. On error the
    /// temporary is removed; the files staged before stay staged until the
    /// set is dropped (which removes them) or committed.
    pub fn stage(&mut self, path: &Path, bytes: &[u8]) -> Result<(), WriteError> {
        self.stage_with(path, |file| file.write_all(bytes))
    }

    /// Stages a file whose content `fill` writes into the temporary.
    fn stage_with(
        &mut self,
        path: &Path,
        fill: impl FnOnce(&mut std::fs::File) -> std::io::Result<()>,
    ) -> Result<(), WriteError> {
        let fail = |cause: std::io::Error| WriteError {
            path: path.to_path_buf(),
            cause,
            written: Vec::new(),
            not_written: vec![path.to_path_buf()],
        };
        let Some(name) = path.file_name() else {
            return Err(fail(std::io::Error::other("not a file name")));
        };
        let dir = path.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or(Path::new("."));
        let serial = SERIAL.fetch_add(1, Ordering::Relaxed);
        let tmp = dir.join(format!(".{}.{}-{serial}.tmp", name.to_string_lossy(), std::process::id()));
        let result = std::fs::File::create(&tmp).and_then(|mut file| {
            fill(&mut file)?;
            file.sync_all()
        });
        match result {
            Ok(()) => {
                self.staged.push((tmp, path.to_path_buf()));
                Ok(())
            }
            Err(cause) => {
                let _ = std::fs::remove_file(&tmp);
                Err(fail(cause))
            }
        }
    }

    /// Renames every staged file into place, in staging order, and returns
    /// the final paths. If a rename fails, the remaining temporaries are
    /// removed and the error says which files were written and which not.
    pub fn commit(mut self) -> Result<Vec<PathBuf>, WriteError> {
        let staged = std::mem::take(&mut self.staged);
        let mut written = Vec::with_capacity(staged.len());
        for (n, (tmp, path)) in staged.iter().enumerate() {
            if let Err(cause) = std::fs::rename(tmp, path) {
                for (t, _) in &staged[n..] {
                    let _ = std::fs::remove_file(t);
                }
                let not_written = staged[n..].iter().map(|(_, p)| p.clone()).collect();
                return Err(WriteError { path: path.clone(), cause, written, not_written });
            }
            written.push(path.clone());
        }
        Ok(written)
    }

    /// Number of staged files.
    pub fn len(&self) -> usize {
        self.staged.len()
    }

    /// Whether nothing is staged.
    pub fn is_empty(&self) -> bool {
        self.staged.is_empty()
    }
}

impl Drop for FileSet {
    fn drop(&mut self) {
        for (tmp, _) in &self.staged {
            let _ = std::fs::remove_file(tmp);
        }
    }
}

/// Writes `bytes` to `path` atomically: a temporary file in the same folder,
/// then a rename. On error the previous file (if any) is untouched and no
/// temporary is left.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), WriteError> {
    let mut set = FileSet::new();
    set.stage(path, bytes)?;
    set.commit().map(|_| ())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn listing(dir: &Path) -> Vec<String> {
        let mut names: Vec<String> = std::fs::read_dir(dir)
            .map(|entries| {
                entries.filter_map(|e| e.ok()).map(|e| e.file_name().to_string_lossy().into_owned()).collect()
            })
            .unwrap_or_default();
        names.sort();
        names
    }

    /// A disk that fills up half-way through a file: the partial temporary
    /// is removed, the earlier version of the file and the files staged
    /// before it are untouched, and nothing else appears in the folder.
    #[test]
    fn a_write_failing_mid_way_leaves_no_temporary() {
        let dir = tempfile::tempdir().unwrap();
        let target = dir.path().join("figure.svg");
        std::fs::write(&target, b"earlier version").unwrap();
        let mut set = FileSet::new();
        set.stage(&dir.path().join("figure.csv"), b"x,y\n1,2\n").unwrap();
        let err = set
            .stage_with(&target, |file| {
                file.write_all(b"<svg>half a fig")?;
                Err(std::io::Error::new(std::io::ErrorKind::StorageFull, "No space left on device"))
            })
            .unwrap_err();
        assert_eq!(err.path, target);
        assert!(err.written.is_empty());
        assert_eq!(err.not_written, vec![target.clone()]);
        assert_eq!(err.to_string(), format!("cannot write {}: No space left on device", target.display()));
        // The set is dropped on the error path of its caller.
        drop(set);
        assert_eq!(listing(dir.path()), vec!["figure.svg".to_string()]);
        assert_eq!(std::fs::read(&target).unwrap(), b"earlier version");
    }

    /// A target that cannot be replaced (here a folder in the file's place)
    /// fails at the rename: the files renamed before it are reported as
    /// written, the rest as not written, and no temporary is left.
    #[test]
    fn a_failed_rename_reports_what_was_written() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::create_dir(dir.path().join("b.png")).unwrap();
        std::fs::create_dir_all(dir.path().join("b.png/inner")).unwrap();
        let mut set = FileSet::new();
        for name in ["a.csv", "b.png", "c.svg"] {
            set.stage(&dir.path().join(name), name.as_bytes()).unwrap();
        }
        assert_eq!(set.len(), 3);
        let err = set.commit().unwrap_err();
        assert_eq!(err.written, vec![dir.path().join("a.csv")]);
        assert_eq!(err.not_written, vec![dir.path().join("b.png"), dir.path().join("c.svg")]);
        let text = err.to_string();
        assert!(text.contains("written: ") && text.contains("not written: "), "{text}");
        assert_eq!(listing(dir.path()), vec!["a.csv".to_string(), "b.png".to_string()]);
    }

    /// A folder that does not exist: the error names the file and nothing
    /// is created.
    #[test]
    fn a_missing_folder_is_named() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("missing/out.csv");
        let err = write_atomically(&path, b"1").unwrap_err();
        assert!(err.to_string().starts_with(&format!("cannot write {}", path.display())), "{err}");
        assert!(listing(dir.path()).is_empty());
    }

    /// A committed set replaces earlier files and leaves only the targets.
    #[test]
    fn a_committed_set_replaces_files() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("a.csv"), b"old").unwrap();
        let mut set = FileSet::new();
        set.stage(&dir.path().join("a.csv"), b"new").unwrap();
        set.stage(&dir.path().join("b.csv"), b"b").unwrap();
        let written = set.commit().unwrap();
        assert_eq!(written.len(), 2);
        assert_eq!(std::fs::read(dir.path().join("a.csv")).unwrap(), b"new");
        assert_eq!(listing(dir.path()), vec!["a.csv".to_string(), "b.csv".to_string()]);
    }
}
