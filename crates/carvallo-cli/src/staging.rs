//! The atomic replacement of a report directory `DIR` by `report --out DIR`.
//!
//! [`Staging::new`] runs before any work: it removes the leftovers of earlier runs that were
//! killed (only the directories of its own naming pattern, `.DIR.carvallo-tmp-*` and
//! `.DIR.carvallo-old-*`, and only those no process holds locked: process ids are reused, locks
//! are not), restores a `DIR` that a killed fallback replacement left absent, and creates the
//! temporary directory `.DIR.carvallo-tmp-PID-NANOS` beside `DIR`, holding an exclusive
//! `flock` on it while it is in use. Creating it is the check that the output directory is
//! writable (`--out /proc/self/x` fails at once, not after the work).
//!
//! [`Staging::commit`] writes the files into it and puts it in place:
//! - with `renameat2(RENAME_EXCHANGE)` (Linux, on the file systems that have it) the new report
//!   and an existing `DIR` swap names in one step, so `DIR` always holds a complete report; the
//!   old one, now under the temporary name, is removed. An absent `DIR` is taken with
//!   `RENAME_NOREPLACE`; if another writer got there first, the two are exchanged instead.
//! - otherwise (the fallback) `DIR` is renamed aside to `.DIR.carvallo-old-PID-NANOS` (locked
//!   first), the new report renamed to `DIR` and the old one removed: a kill between the two
//!   renames leaves `DIR` absent, and the next run restores it from the old report.
//!
//! Ctrl-C (SIGINT) while the report is computed or written removes the temporary directory
//! and exits with code 130; during the renames themselves it waits for them to finish.
//!
//! In debug builds (the tests), `CARVALLO_TEST_KILL_AT=STEP` kills the process with SIGKILL at
//! the step named (`staged`, `written`, `exchanged`, `aside`, `replaced`) and
//! `CARVALLO_TEST_NO_EXCHANGE=1` takes the fallback; release builds have neither hook.

use std::fs::File;
use std::os::unix::io::AsRawFd as _;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

use anyhow::{Context, Result};

use crate::report_dir::{BadInput, MARKER};

/// The temporary directory of the report being written, for the Ctrl-C handler to remove.
/// Held locked while the directories are renamed, so that Ctrl-C waits for the renames.
static IN_FLIGHT: Mutex<Option<PathBuf>> = Mutex::new(None);

/// A locked temporary directory beside `DIR` that receives the report.
pub struct Staging {
    dir: PathBuf,
    tmp: PathBuf,
    /// The open directory holding the `flock` (released when dropped).
    _lock: File,
    committed: bool,
}

/// The prefix of the temporary and set-aside directories of `DIR` (`.DIR.carvallo-`).
fn prefix(dir: &Path) -> String {
    let name = dir.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    format!(".{name}.carvallo-")
}

/// A name no other process uses at the same time: the process id and the clock's nanoseconds.
fn unique() -> String {
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.subsec_nanos());
    format!("{}-{nanos}", std::process::id())
}

/// Opens the directory `path` and takes an exclusive `flock` on it without waiting: `None` when
/// another process holds it (or it cannot be opened).
fn try_lock(path: &Path) -> Option<File> {
    let file = File::open(path).ok()?;
    // SAFETY: flock on a descriptor owned by `file`, which outlives the call.
    let r = unsafe { libc::flock(file.as_raw_fd(), libc::LOCK_EX | libc::LOCK_NB) };
    (r == 0).then_some(file)
}

/// In debug builds, kills the process (SIGKILL: no clean-up runs) when `CARVALLO_TEST_KILL_AT`
/// names `step`.
fn kill_point(step: &str) {
    if cfg!(debug_assertions) && std::env::var("CARVALLO_TEST_KILL_AT").is_ok_and(|s| s == step) {
        // SAFETY: sends a signal to this process.
        unsafe {
            libc::kill(libc::getpid(), libc::SIGKILL);
        }
    }
}

/// The flags of `renameat2`: fail if the target exists; swap the two names.
const NOREPLACE: u32 = 1;
const EXCHANGE: u32 = 2;
#[cfg(target_os = "linux")]
const _: () = assert!(NOREPLACE == libc::RENAME_NOREPLACE && EXCHANGE == libc::RENAME_EXCHANGE);

/// `renameat2(from, to, flags)` in the current directory's terms; `Err` carries the OS error
/// (`EINVAL` where the system has no `renameat2`: the fallback).
#[cfg(not(target_os = "linux"))]
fn rename2(_: &Path, _: &Path, _: u32) -> std::io::Result<()> {
    Err(std::io::Error::from_raw_os_error(libc::EINVAL))
}

/// `renameat2(from, to, flags)` in the current directory's terms; `Err` carries the OS error.
#[cfg(target_os = "linux")]
fn rename2(from: &Path, to: &Path, flags: u32) -> std::io::Result<()> {
    if cfg!(debug_assertions) && std::env::var_os("CARVALLO_TEST_NO_EXCHANGE").is_some() {
        return Err(std::io::Error::from_raw_os_error(libc::EINVAL));
    }
    use std::os::unix::ffi::OsStrExt as _;
    let c = |p: &Path| {
        std::ffi::CString::new(p.as_os_str().as_bytes())
            .map_err(|e| std::io::Error::new(std::io::ErrorKind::InvalidInput, e))
    };
    let (from, to) = (c(from)?, c(to)?);
    // SAFETY: two NUL-terminated paths that live across the call.
    let r = unsafe {
        libc::renameat2(libc::AT_FDCWD, from.as_ptr(), libc::AT_FDCWD, to.as_ptr(), flags)
    };
    if r == 0 {
        Ok(())
    } else {
        Err(std::io::Error::last_os_error())
    }
}

/// Whether `e` says that `renameat2` or its flag is not available here (the fallback applies).
fn unsupported(e: &std::io::Error) -> bool {
    matches!(e.raw_os_error(), Some(libc::EINVAL | libc::ENOSYS | libc::ENOTSUP))
}

/// Removes the unlocked leftovers of `dir`'s naming pattern in `parent`, after restoring an
/// absent `dir` from a complete set-aside report.
fn clean_leftovers(dir: &Path, parent: &Path) {
    let prefix = prefix(dir);
    let Ok(entries) = std::fs::read_dir(parent) else { return };
    let mut leftovers: Vec<PathBuf> = entries
        .filter_map(|e| e.ok())
        .filter(|e| e.file_name().to_string_lossy().starts_with(&prefix))
        .map(|e| e.path())
        .collect();
    leftovers.sort();
    for path in leftovers {
        let Some(_lock) = try_lock(&path) else { continue };
        // A directory just created by another run, before it took its lock: left alone (a
        // killed run's empty directory is removed once it is ten seconds old).
        let empty = std::fs::read_dir(&path).is_ok_and(|mut d| d.next().is_none());
        let age = std::fs::metadata(&path)
            .and_then(|m| m.modified())
            .ok()
            .and_then(|t| t.elapsed().ok())
            .unwrap_or_default();
        if empty && age < std::time::Duration::from_secs(10) {
            continue;
        }
        let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        let old = name[prefix.len()..].starts_with("old-");
        // A killed fallback: DIR absent, the previous report set aside complete.
        if old
            && !dir.exists()
            && path.join(MARKER).is_file()
            && std::fs::rename(&path, dir).is_ok()
        {
            continue;
        }
        let _ = std::fs::remove_dir_all(&path);
    }
}

impl Staging {
    /// Cleans up after killed runs and creates the locked temporary directory of `dir` in
    /// `parent` (see the module docs); an error is a directory that cannot be written.
    pub fn new(dir: &Path, parent: &Path) -> Result<Staging, BadInput> {
        clean_leftovers(dir, parent);
        let tmp = parent.join(format!("{}tmp-{}", prefix(dir), unique()));
        std::fs::create_dir(&tmp).map_err(|e| {
            BadInput(format!(
                "cannot write to the output directory's parent `{}`: {}",
                parent.display(),
                e.to_string().to_lowercase()
            ))
        })?;
        // Waits for a cleaning run that holds it a moment (it leaves a fresh empty one alone).
        let lock = File::open(&tmp).and_then(|f| {
            // SAFETY: flock on a descriptor owned by `f`, which outlives the call.
            match unsafe { libc::flock(f.as_raw_fd(), libc::LOCK_EX) } {
                0 => Ok(f),
                _ => Err(std::io::Error::last_os_error()),
            }
        });
        let lock = match lock {
            Ok(lock) => lock,
            Err(e) => {
                let _ = std::fs::remove_dir(&tmp);
                return Err(BadInput(format!("cannot lock `{}`: {e}", tmp.display())));
            }
        };
        install_handler();
        *IN_FLIGHT.lock().unwrap_or_else(|e| e.into_inner()) = Some(tmp.clone());
        kill_point("staged");
        Ok(Staging { dir: dir.to_path_buf(), tmp, _lock: lock, committed: false })
    }

    /// Writes `files` (name, text) into the temporary directory and puts it in place of `DIR`.
    pub fn commit(mut self, files: &[(String, String)]) -> Result<()> {
        for (name, text) in files {
            let path = self.tmp.join(name);
            std::fs::write(&path, text)
                .with_context(|| format!("cannot write `{}`", path.display()))?;
        }
        kill_point("written");
        // Ctrl-C waits until the directories are in place.
        let mut flight = IN_FLIGHT.lock().unwrap_or_else(|e| e.into_inner());
        let result = self.replace();
        if result.is_ok() {
            self.committed = true;
        }
        *flight = None;
        result
    }

    /// Puts the temporary directory at `DIR`.
    fn replace(&self) -> Result<()> {
        let (tmp, dir) = (&self.tmp, &self.dir);
        let cannot = || format!("cannot rename `{}` to `{}`", tmp.display(), dir.display());
        loop {
            match rename2(tmp, dir, NOREPLACE) {
                Ok(()) => return Ok(()),
                Err(e) if unsupported(&e) => return self.replace_fallback(),
                Err(e) if e.raw_os_error() == Some(libc::EEXIST) => {}
                Err(e) => return Err(e).with_context(cannot),
            }
            match rename2(tmp, dir, EXCHANGE) {
                Ok(()) => {
                    kill_point("exchanged");
                    // The previous report, now under the temporary name.
                    let _ = std::fs::remove_dir_all(tmp);
                    return Ok(());
                }
                Err(e) if unsupported(&e) => return self.replace_fallback(),
                // DIR vanished between the two calls (another writer's fallback): again.
                Err(e) if e.raw_os_error() == Some(libc::ENOENT) => {}
                Err(e) => return Err(e).with_context(cannot),
            }
        }
    }

    /// The fallback without `renameat2`: `DIR` renamed aside (locked), the new report renamed
    /// to `DIR`, the old one removed.
    fn replace_fallback(&self) -> Result<()> {
        let (tmp, dir) = (&self.tmp, &self.dir);
        let parent = tmp.parent().unwrap_or(Path::new("."));
        let old = parent.join(format!("{}old-{}", prefix(dir), unique()));
        let moved = dir.exists();
        // Locked, so that no other run restores or removes it while it is aside (`None` when
        // another process still holds the report it wrote: the rename goes on regardless).
        let _held = if moved {
            let lock = try_lock(dir);
            std::fs::rename(dir, &old)
                .with_context(|| format!("cannot move `{}` aside", dir.display()))?;
            kill_point("aside");
            lock
        } else {
            None
        };
        if let Err(e) = std::fs::rename(tmp, dir) {
            if moved {
                let _ = std::fs::rename(&old, dir);
            }
            return Err(e).with_context(|| {
                format!("cannot rename `{}` to `{}`", tmp.display(), dir.display())
            });
        }
        kill_point("replaced");
        if moved {
            let _ = std::fs::remove_dir_all(&old);
        }
        Ok(())
    }
}

impl Drop for Staging {
    /// Removes the temporary directory of a report not committed (an error while writing).
    fn drop(&mut self) {
        if !self.committed {
            let mut flight = IN_FLIGHT.lock().unwrap_or_else(|e| e.into_inner());
            let _ = std::fs::remove_dir_all(&self.tmp);
            *flight = None;
        }
    }
}

/// Installs the Ctrl-C handler once: it removes the temporary directory in flight (waiting for
/// renames under way) and exits with code 130.
fn install_handler() {
    static HANDLER: std::sync::Once = std::sync::Once::new();
    HANDLER.call_once(|| {
        // An error only means Ctrl-C keeps its default effect (the next run cleans up).
        let _ = ctrlc::set_handler(|| {
            let flight = IN_FLIGHT.lock().unwrap_or_else(|e| e.into_inner());
            if let Some(tmp) = flight.as_ref() {
                let _ = std::fs::remove_dir_all(tmp);
            }
            let _ = std::io::Write::write_all(&mut std::io::stderr(), b"interrupted\n");
            std::process::exit(130);
        });
    });
}
