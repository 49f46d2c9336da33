//! What builds keep on disk: an output folder's packs and cache ([`cache`]), and the module cache
//! builds, processes and machines share ([`shared`]), and on a server ([`remote`]). Every file is written whole or not at all
//! and verified on read, so damage costs a recompile, never a wrong module.

mod cache;
mod credentials;
mod pass_index;
mod records;
pub mod remote;
pub mod shared;

pub use cache::{
    Cache, Digest, Hashed, ModuleBytes, OutputFile, OutputLock, PassKey, PlannedPack, Recorded, RecordedFile,
    RecordedFinding, RecordedLabel, SealedEntry, Staged, durable, durable_folder, hash, link_or_copy,
    pass_index_path, seal, sealed, stage, unsealed, write_atomically,
};
pub use pass_index::{CachedStage, PassIndex, PassIndexView};
