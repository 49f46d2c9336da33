//! The driver's pipeline cache kept between runs: a file per adapter (named by
//! `wgpu::util::pipeline_cache_key`) in a folder the program chooses, loaded under wgpu's
//! contract and written atomically after warm-up and at exit.
//!
//! The file is kiln's own: a magic line, a header naming what made it (the adapter's name,
//! vendor, device, driver and driver info, and wgpu's version), a BLAKE3 hash of the header and
//! the data, then the driver's data. wgpu's own header check covers vendor and device, but its
//! "hash" field is a constant in wgpu-core 30.0.1, so kiln checks its hash before any byte reaches
//! the driver's `unsafe` call; a file that fails starts an empty cache.

use super::pipelines::Runtime;
use std::path::{Path, PathBuf};

/// What [`Runtime::open_pipeline_cache`] found.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum CacheFile {
    /// The adapter's file, of this many bytes (kiln's header and the driver's data), whose data
    /// was given to the driver (which starts empty where wgpu's own header names another vendor
    /// or device).
    Loaded {
        /// The file.
        path: PathBuf,
        /// Its size.
        bytes: u64,
    },
    /// No file yet: the cache starts empty and [`Runtime::save_pipeline_cache`] writes it.
    Empty {
        /// The file it will be.
        path: PathBuf,
    },
    /// A file that is not what [`Runtime::save_pipeline_cache`] wrote on this adapter (another
    /// adapter's or driver's, torn, changed since, or not kiln's): none of it reaches the driver;
    /// the cache starts empty and the next save replaces it.
    Discarded {
        /// The file.
        path: PathBuf,
        /// Why, in a few words.
        why: &'static str,
    },
    /// The backend keeps no pipeline cache in wgpu 30 (DX12, Metal, GL; only Vulkan does), or
    /// the device lacks `Features::PIPELINE_CACHE`: warm-up from a trace does the work alone.
    Unsupported,
}

impl Runtime {
    /// Starts the pipeline cache of every pipeline made from now on from the file for `adapter`
    /// in `dir` (created when saved; a platform's data folder, such as
    /// `$XDG_CACHE_HOME/<game>` on Linux, `%LOCALAPPDATA%\<game>` on Windows or
    /// `~/Library/Caches/<game>` on macOS). A file that cannot be read starts an empty cache.
    ///
    /// # Safety
    ///
    /// wgpu's `Device::create_pipeline_cache` contract: the file must hold what
    /// [`Runtime::save_pipeline_cache`] wrote (`PipelineCache::get_data`) on this kind of
    /// adapter. kiln checks its own header (the adapter, the driver, wgpu's version) and a hash
    /// of the header and the data, and starts empty where either does not match, so damage and
    /// another adapter's file never reach the driver; a file made to pass both by someone who
    /// can write the folder still does.
    pub unsafe fn open_pipeline_cache(&mut self, adapter: &wgpu::AdapterInfo, dir: &Path) -> CacheFile {
        let key = wgpu::util::pipeline_cache_key(adapter);
        let supported = self.device.features().contains(wgpu::Features::PIPELINE_CACHE);
        let (Some(key), true) = (key, supported) else { return CacheFile::Unsupported };
        let path = dir.join(key);
        let file = std::fs::read(&path).ok();
        let (data, why) = match file.as_deref().map(|file| unwrapped(file, adapter)) {
            None => (None, None),
            Some(Ok(data)) => (Some(data), None),
            Some(Err(why)) => (None, Some(why)),
        };
        // SAFETY: the caller vouches for the file's origin (this function's contract).
        let cache = unsafe {
            self.device.create_pipeline_cache(&wgpu::PipelineCacheDescriptor {
                label: Some("kiln"),
                data,
                fallback: true,
            })
        };
        self.wgpu_cache = Some(cache);
        self.cache_file = Some((path.clone(), header(adapter)));
        let loaded = data.is_some();
        match (file.map(|file| file.len() as u64), loaded, why) {
            (_, _, Some(why)) => CacheFile::Discarded { path, why },
            (Some(bytes), true, None) => CacheFile::Loaded { path, bytes },
            _ => CacheFile::Empty { path },
        }
    }

    /// Writes the pipeline cache to the file [`Runtime::open_pipeline_cache`] named, under a
    /// temporary name renamed over it, so the file is the old cache or the new one, never half;
    /// returns its size (`None`: no cache file is open, or the driver gave no data).
    pub fn save_pipeline_cache(&self) -> std::io::Result<Option<u64>> {
        let (Some((path, header)), Some(data)) = (&self.cache_file, self.pipeline_cache_data()) else {
            return Ok(None);
        };
        if let Some(dir) = path.parent() {
            std::fs::create_dir_all(dir)?;
        }
        let file = wrapped(&data, header);
        write_atomically(path, &file)?;
        Ok(Some(file.len() as u64))
    }
}

/// Writes `bytes` under a temporary name beside `path`, made durable, then renamed over it: a
/// reader sees the old file or the new one. (The compiler's store has its own, with staging for
/// streamed files; a game needs only this.)
fn write_atomically(path: &std::path::Path, bytes: &[u8]) -> std::io::Result<()> {
    let mut temporary = path.as_os_str().to_owned();
    temporary.push(format!(".{}.tmp", std::process::id()));
    let temporary = std::path::PathBuf::from(temporary);
    let written = std::fs::write(&temporary, bytes)
        .and_then(|()| std::fs::File::open(&temporary)?.sync_all())
        .and_then(|()| std::fs::rename(&temporary, path));
    if written.is_err() {
        let _ = std::fs::remove_file(&temporary);
    }
    written
}

/// The first line of every pipeline cache file kiln writes.
const MAGIC: &[u8] = b"kiln pipeline cache 1\n";

/// What made a cache file: the adapter and its driver, and wgpu's version (the data's format).
fn header(adapter: &wgpu::AdapterInfo) -> String {
    format!(
        "adapter {:?}\nvendor {:#x} device {:#x}\ndriver {:?}\ndriver info {:?}\nbackend {:?}\nwgpu 30\n",
        adapter.name, adapter.vendor, adapter.device, adapter.driver, adapter.driver_info, adapter.backend
    )
}

/// The driver's `data` in kiln's file: the magic line, the header's length and the header, the
/// hash of both and the data, the data.
fn wrapped(data: &[u8], header: &str) -> Vec<u8> {
    let mut hasher = blake3::Hasher::new();
    hasher.update(header.as_bytes()).update(data);
    let mut file = Vec::with_capacity(MAGIC.len() + 4 + header.len() + 32 + data.len());
    file.extend_from_slice(MAGIC);
    file.extend_from_slice(&(header.len() as u32).to_le_bytes());
    file.extend_from_slice(header.as_bytes());
    file.extend_from_slice(hasher.finalize().as_bytes());
    file.extend_from_slice(data);
    file
}

/// The driver's data in a file [`wrapped`] wrote for this adapter, or why it is not one.
fn unwrapped<'a>(file: &'a [u8], adapter: &wgpu::AdapterInfo) -> Result<&'a [u8], &'static str> {
    let rest = file.strip_prefix(MAGIC).ok_or("not a pipeline cache file kiln wrote")?;
    let (length, rest) = rest.split_first_chunk::<4>().ok_or("torn")?;
    let length = u32::from_le_bytes(*length) as usize;
    let (written, rest) = rest.split_at_checked(length).ok_or("torn")?;
    if written != header(adapter).as_bytes() {
        return Err("made on another adapter, driver or wgpu");
    }
    let (hash, data) = rest.split_first_chunk::<32>().ok_or("torn")?;
    let mut hasher = blake3::Hasher::new();
    hasher.update(written).update(data);
    if hasher.finalize().as_bytes() != hash {
        return Err("its bytes are not those written (torn or changed)");
    }
    Ok(data)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn adapter(driver: &str) -> wgpu::AdapterInfo {
        wgpu::AdapterInfo {
            name: "llvmpipe".into(),
            vendor: 0x10005,
            device: 0,
            device_type: wgpu::DeviceType::Cpu,
            driver: driver.into(),
            driver_info: "Mesa 22.3.6".into(),
            backend: wgpu::Backend::Vulkan,
            device_pci_bus_id: String::new(),
            subgroup_min_size: 4,
            subgroup_max_size: 8,
            transient_saves_memory: None,
            limit_bucket: None,
        }
    }

    #[test]
    fn a_cache_file_reaches_the_driver_only_as_written_for_its_adapter() {
        let data = b"the driver's own bytes".to_vec();
        let file = wrapped(&data, &header(&adapter("llvmpipe")));
        assert_eq!(unwrapped(&file, &adapter("llvmpipe")), Ok(&data[..]));
        assert!(unwrapped(&file, &adapter("another driver")).is_err(), "another driver's file");
        for at in [0, MAGIC.len() + 2, file.len() - 1] {
            let mut changed = file.clone();
            changed[at] ^= 1;
            assert!(unwrapped(&changed, &adapter("llvmpipe")).is_err(), "a byte changed at {at}");
        }
        for cut in [0, 10, MAGIC.len() + 4, file.len() - 1] {
            assert!(unwrapped(&file[..cut], &adapter("llvmpipe")).is_err(), "cut at {cut}");
        }
        assert!(unwrapped(&data, &adapter("llvmpipe")).is_err(), "wgpu's data alone, as kiln 0.1 wrote it");
    }
}
