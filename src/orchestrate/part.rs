//! A pass's part of the manifest, made on the pass's own thread from what its jobs compiled:
//! each module once, each distinct interface, uniform block and pack once, its variants as
//! module indices, and what the pass's source says (render state, keyword sets).

use super::jobs::Job;
use super::plan::PassWork;
use crate::catalog::{Catalog, property_references};
use crate::manifest::*;
use crate::material::MaterialValue;
use crate::reflect::{StageReflection, UniformBlock};
use crate::shaderlab::pragma::KeywordKind;
use crate::source::SourceStore;
use crate::store::CachedStage;
use std::collections::{BTreeMap, HashMap};

/// What a pass compiled: its jobs, each job's stage (`None` where it failed), and the jobs of each
/// variant and of the ubershader, by index into `jobs`.
pub(super) struct CompiledPass<'a> {
    pub jobs: &'a [Job<'a>],
    pub built: &'a [Option<CachedStage>],
    pub variants: &'a [Vec<Option<usize>>],
    pub ubershader: Option<&'a [Option<usize>]>,
}

/// A pass's part of the manifest.
pub(super) fn pass_manifest(
    store: &SourceStore,
    catalog: &Catalog,
    work: &PassWork,
    compiled: &CompiledPass,
) -> PassManifest {
    let table = ModuleTable::of(compiled.jobs, compiled.built);
    let compute = !work.program.pragmas.kernels.is_empty();
    let variants = work
        .variants
        .iter()
        .zip(compiled.variants)
        .map(|(variant, jobs)| VariantManifest {
            key: variant.bits.key(),
            keywords: work.program.keywords.keywords(&variant.bits).map(str::to_string).collect(),
            materials: variant.materials.iter().map(|&m| catalog.materials[m].name.clone()).collect(),
            ..table.variant(compute, jobs)
        })
        .collect();
    let ubershader = compiled.ubershader.map(|jobs| Ubershader {
        keywords: work.program.pragmas.ubershader_keywords().into_iter().map(str::to_string).collect(),
        modules: table.variant(compute, jobs),
    });
    PassManifest {
        subshader: work.pass.subshader,
        index: work.pass.index,
        name: work.pass.name.clone(),
        tags: work.pass.tags.clone(),
        render_state: render_state(store, work),
        keyword_sets: keyword_sets(work),
        keywords: work.program.keywords.names().to_vec(),
        kernels: work.program.pragmas.kernels.iter().map(|k| k.value.clone()).collect(),
        layout: table.layout,
        uniform_blocks: table.uniform_blocks,
        packs: table.packs,
        interfaces: table.interfaces,
        modules: table.modules,
        variants,
        ubershader,
    }
}

// Sized for every job once: grown a push at a time, they cost a pass's end more than the rest of
// it (compute 1,000, 200 jobs a pass).
type Map<K> = HashMap<K, usize, foldhash::fast::FixedState>;

fn sized<K>(jobs: usize) -> Map<K> {
    Map::with_capacity_and_hasher(jobs, Default::default())
}

/// A pass's distinct modules and what they share, and each job's module.
struct ModuleTable {
    layout: Vec<BindGroup>,
    uniform_blocks: Vec<UniformBlock>,
    packs: Vec<PackPath>,
    interfaces: Vec<StageInterface>,
    modules: Vec<ModuleManifest>,
    /// For each job, its module (`None` when it failed).
    module_of_job: Vec<Option<usize>>,
}

impl ModuleTable {
    fn of<'a>(jobs: &[Job], built: &'a [Option<CachedStage>]) -> ModuleTable {
        let mut entries: BTreeMap<(u32, u32), LayoutEntry> = BTreeMap::new();
        let mut uniform_blocks: Vec<UniformBlock> = Vec::new();
        let mut packs: Vec<PackPath> = Vec::new();
        let mut pack_of: Map<&PackPath> = Map::default();
        let mut interfaces: Vec<StageInterface> = Vec::with_capacity(jobs.len());
        let mut interface_of: Map<StageInterface> = sized(jobs.len());
        let mut modules: Vec<ModuleManifest> = Vec::with_capacity(jobs.len());
        // A module is its interface, its files' hashes and the features it was validated with.
        type ModuleIdentity<'a> = (usize, PerBackend<Option<&'a str>>, Vec<GpuFeature>);
        let mut module_of: Map<ModuleIdentity> = sized(jobs.len());
        let mut module_of_job: Vec<Option<usize>> = Vec::with_capacity(jobs.len());
        for (job, stage) in jobs.iter().zip(built) {
            let Some(stage) = stage else {
                module_of_job.push(None);
                continue;
            };
            let name = job.stage.shader_stage();
            for b in &stage.reflection.bindings {
                let entry = entries.entry((b.group, b.binding)).or_insert_with(|| LayoutEntry {
                    binding: b.binding,
                    name: b.name.clone(),
                    visibility: Vec::new(),
                    resource: b.resource.clone(),
                });
                if !entry.visibility.contains(&name) {
                    entry.visibility.push(name);
                }
            }
            let interface = stage_interface(name, &stage.reflection, &mut uniform_blocks);
            let interface = *interface_of.entry(interface).or_insert_with_key(|interface| {
                interfaces.push(interface.clone());
                interfaces.len() - 1
            });
            let mut file = |file: &'a Option<FileRef>| {
                file.as_ref().map(|f| {
                    let pack = *pack_of.entry(&f.path).or_insert_with(|| {
                        packs.push(f.path.clone());
                        packs.len() - 1
                    });
                    ModuleFile { pack, offset: f.offset, size: f.size, hash: f.hash.clone() }
                })
            };
            // Texts that differ only where compaction removes code give the same module.
            let hashes =
                PerBackend::from_fn(|backend| stage.files[backend].as_ref().map(|f| f.hash.as_str()));
            let module =
                *module_of.entry((interface, hashes, job.allowed.features())).or_insert_with_key(|key| {
                    let files = PerBackend::from_fn(|backend| file(&stage.files[backend]));
                    modules.push(ModuleManifest::with_files(interface, key.2.clone(), files));
                    modules.len() - 1
                });
            module_of_job.push(Some(module));
        }
        let mut groups: BTreeMap<u32, Vec<LayoutEntry>> = BTreeMap::new();
        for ((group, _), mut entry) in entries {
            entry.visibility.sort();
            groups.entry(group).or_default().push(entry);
        }
        let layout = groups.into_iter().map(|(group, entries)| BindGroup { group, entries }).collect();
        ModuleTable { layout, uniform_blocks, packs, interfaces, modules, module_of_job }
    }

    /// A variant's modules, from its jobs: a compute pass's entries are its kernels, a render
    /// pass's its two stages.
    fn variant(&self, compute: bool, jobs: &[Option<usize>]) -> VariantManifest {
        let module = |job: Option<&Option<usize>>| job.copied().flatten().and_then(|j| self.module_of_job[j]);
        let (vertex, fragment, kernels) = if compute {
            (None, None, (0..jobs.len()).map(|k| module(jobs.get(k))).collect())
        } else {
            (module(jobs.first()), module(jobs.get(1)), Vec::new())
        };
        VariantManifest {
            key: String::new(),
            keywords: Vec::new(),
            materials: Vec::new(),
            vertex,
            fragment,
            kernels,
        }
    }
}

/// A stage's interface, its uniform blocks added to the pass's (each once) and named by index in
/// name order.
fn stage_interface(
    stage: ShaderStage,
    reflection: &StageReflection,
    pass_blocks: &mut Vec<UniformBlock>,
) -> StageInterface {
    let mut blocks: Vec<usize> = reflection
        .uniform_blocks
        .iter()
        .map(|block| {
            pass_blocks.iter().position(|b| b == block).unwrap_or_else(|| {
                pass_blocks.push(block.clone());
                pass_blocks.len() - 1
            })
        })
        .collect();
    blocks.sort_by(|&a, &b| pass_blocks[a].name.cmp(&pass_blocks[b].name));
    StageInterface {
        stage,
        entry_point: reflection.entry_point.clone(),
        inputs: reflection.inputs.clone(),
        outputs: reflection.outputs.clone(),
        bindings: reflection.bindings.iter().map(|b| [b.group, b.binding]).collect(),
        uniform_blocks: blocks,
        overrides: reflection.overrides.clone(),
        workgroup_size: reflection.workgroup_size,
        workgroup_size_overrides: reflection.workgroup_size_overrides.clone(),
        workgroup_memory: reflection.workgroup_memory,
    }
}

/// The pass's render state, its subshader's commands then its own, each with the properties it
/// names and their defaults.
fn render_state(store: &SourceStore, work: &PassWork) -> Vec<RenderState> {
    let shader = &work.shader.shader;
    let subshader = shader.subshaders.get(work.pass.subshader).map(|sub| &sub.state.render_state);
    let pass = work.shader.pass_ast(work.pass).map(|p| &p.state.render_state);
    (subshader.into_iter().flatten())
        .chain(pass.into_iter().flatten())
        .map(|command| {
            let text = store.slice(command.span).trim().to_string();
            let properties = property_references(&text)
                .into_iter()
                .map(|name| PropertyReference {
                    default: shader
                        .property(name)
                        .map_or(serde_json::Value::Null, |p| MaterialValue::from(&p.default.value).to_json()),
                    name: name.to_string(),
                })
                .collect();
            RenderState { command: text, state: command.kind.to_manifest(), properties }
        })
        .collect()
}

/// The pass's keyword sets: those that make variants, then the `dynamic_branch` ones.
fn keyword_sets(work: &PassWork) -> Vec<KeywordSetManifest> {
    let dynamic = work.program.pragmas.keyword_sets.iter().filter(|s| s.kind == KeywordKind::DynamicBranch);
    (work.program.keywords.sets().iter())
        .chain(dynamic)
        .map(|set| KeywordSetManifest {
            kind: set.kind,
            scope: set.scope,
            stage: set.stage,
            keywords: set.options.iter().map(|o| o.keyword.clone().unwrap_or_else(|| "_".into())).collect(),
        })
        .collect()
}
