//! kiln's integration tests: one binary, one module per concern. Golden files are regenerated
//! with `UPDATE_EXPECT=1 cargo test`, then reviewed like code.

#[global_allocator]
static ALLOCATOR: support::CountingAllocator = support::CountingAllocator;

mod accuracy;
mod backends;
mod bad;
mod build;
mod cache;
mod cli;
mod compute;
mod confinement;
mod conformance;
mod cpp;
mod docs;
mod dynamic;
mod features;
mod fingerprint;
mod gpu;
mod hlsl;
mod hostile;
mod integrity;
mod layouts;
mod list;
mod lsp;
mod lsp_client;
mod lsp_edits;
mod materials;
mod parse;
mod preprocess;
mod preview;
mod reach;
mod remote;
mod render_state;
mod robustness;
mod runtime;
mod scale;
mod shards;
mod shipping;
mod support;
mod tidy;
mod together;
mod trust;
mod ubershader;
mod unity_corpus;
mod validators;
mod wgsl_corpora;
