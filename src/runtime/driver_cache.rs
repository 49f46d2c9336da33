//! The driver's pipeline cache kept between runs: a file per adapter (named by
//! `wgpu::util::pipeline_cache_key`) in a folder the program chooses, loaded under wgpu's
//! contract and written atomically after warm-up and at exit.

use super::pipelines::Runtime;
use std::path::{Path, PathBuf};

/// What [`Runtime::open_pipeline_cache`] found.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum CacheFile {
    /// The adapter's file, this many bytes, given to the driver (which starts empty where its
    /// header names another vendor, device or driver version).
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
    /// adapter. wgpu checks the header it wrote (its version, the adapter's vendor and device,
    /// a hash of the data) and starts empty where it does not match, but bytes from anywhere else
    /// that pass that check reach the driver.
    pub unsafe fn open_pipeline_cache(&mut self, adapter: &wgpu::AdapterInfo, dir: &Path) -> CacheFile {
        let key = wgpu::util::pipeline_cache_key(adapter);
        let supported = self.device.features().contains(wgpu::Features::PIPELINE_CACHE);
        let (Some(key), true) = (key, supported) else { return CacheFile::Unsupported };
        let path = dir.join(key);
        let data = std::fs::read(&path).ok();
        // SAFETY: the caller vouches for the file's origin (this function's contract).
        let cache = unsafe {
            self.device.create_pipeline_cache(&wgpu::PipelineCacheDescriptor {
                label: Some("kiln"),
                data: data.as_deref(),
                fallback: true,
            })
        };
        self.wgpu_cache = Some(cache);
        self.cache_file = Some(path.clone());
        match data {
            Some(data) => CacheFile::Loaded { path, bytes: data.len() as u64 },
            None => CacheFile::Empty { path },
        }
    }

    /// Writes the pipeline cache to the file [`Runtime::open_pipeline_cache`] named, under a
    /// temporary name renamed over it, so the file is the old cache or the new one, never half;
    /// returns its size (`None`: no cache file is open, or the driver gave no data).
    pub fn save_pipeline_cache(&self) -> std::io::Result<Option<u64>> {
        let (Some(path), Some(data)) = (&self.cache_file, self.pipeline_cache_data()) else {
            return Ok(None);
        };
        if let Some(dir) = path.parent() {
            std::fs::create_dir_all(dir)?;
        }
        crate::store::write_atomically(path, &data)?;
        Ok(Some(data.len() as u64))
    }
}
