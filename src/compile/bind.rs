//! Binding assignment: resources without `@group`/`@binding` get them by update frequency (group 0
//! per frame, 1 per material, 2 per object), the same for every variant of a pass so that one
//! bind group layout serves all of them. Explicit attributes win and are checked for clashes.

use crate::manifest::{FRAME_GROUP, MATERIAL_GROUP, OBJECT_GROUP};
use naga::{
    AddressSpace, Expression, GlobalVariable, Handle, Module, ResourceBinding, ShaderStage, Statement,
};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::collections::HashSet;

/// Resources the renderer updates once per frame, and once per object; everything else is the
/// material's.
const PER_FRAME_NAMES: [&str; 2] = ["UnityPerFrame", "_CustomLight"];
const PER_OBJECT_NAMES: [&str; 1] = ["UnityPerDraw"];

/// The names a project adds to the per-frame and per-object groups (`[bind_groups]` in
/// `kiln.toml`), besides kiln's own.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct GroupNames {
    /// Resources bound once per frame (group 0).
    pub per_frame: Vec<String>,
    /// Resources bound once per object (group 2).
    pub per_object: Vec<String>,
}

/// The group a resource without an explicit `@group` goes to.
pub fn group_for(name: &str, names: &GroupNames) -> u32 {
    if PER_FRAME_NAMES.contains(&name) || names.per_frame.iter().any(|n| n == name) {
        FRAME_GROUP
    } else if PER_OBJECT_NAMES.contains(&name) || names.per_object.iter().any(|n| n == name) {
        OBJECT_GROUP
    } else {
        MATERIAL_GROUP
    }
}

/// A resource a module declares, with where (in the preprocessed text) it is declared.
#[derive(Debug, Clone, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct Declared {
    /// The resource's global variable name.
    pub name: String,
    /// `@group`/`@binding` written in the source, if any.
    pub explicit: Option<(u32, u32)>,
    /// Where it is declared in the preprocessed text (byte range).
    pub range: (u32, u32),
}

fn is_resource(space: AddressSpace) -> bool {
    matches!(space, AddressSpace::Uniform | AddressSpace::Storage { .. } | AddressSpace::Handle)
}

/// The resources an entry point of a parsed module reaches (directly or through the functions it
/// calls), in declaration order: those the stage's module keeps once compacted, and so the only
/// ones its pass's layout and clash checks should see. All of them when the entry point is not
/// there (the stage reports that).
pub fn declared(module: &Module, entry: &str, stage: ShaderStage) -> Vec<Declared> {
    let reached =
        module.entry_points.iter().find(|e| e.name == entry && e.stage == stage).map(|e| reached(module, e));
    module
        .global_variables
        .iter()
        .filter(|(handle, g)| is_resource(g.space) && reached.as_ref().is_none_or(|r| r.contains(handle)))
        .map(|(handle, g)| {
            let range = module.global_variables.get_span(handle).to_range().unwrap_or(0..0);
            Declared {
                name: g.name.clone().unwrap_or_default(),
                explicit: g.binding.as_ref().map(|b| (b.group, b.binding)),
                range: (range.start as u32, range.end as u32),
            }
        })
        .collect()
}

/// The global variables an entry point uses, through every function it calls.
fn reached(module: &Module, entry: &naga::EntryPoint) -> HashSet<Handle<GlobalVariable>> {
    let mut globals = HashSet::new();
    let mut called = HashSet::new();
    let mut pending = vec![&entry.function];
    while let Some(function) = pending.pop() {
        for (_, expression) in function.expressions.iter() {
            if let Expression::GlobalVariable(global) = expression {
                globals.insert(*global);
            }
        }
        // Every call is a statement (a call's result is an expression only besides).
        let mut calls = Vec::new();
        statement_calls(&function.body, &mut calls);
        for callee in calls {
            if called.insert(callee) {
                pending.push(&module.functions[callee]);
            }
        }
    }
    globals
}

/// The functions a block calls, nested blocks included.
fn statement_calls(block: &naga::Block, out: &mut Vec<Handle<naga::Function>>) {
    for statement in block.iter() {
        match statement {
            Statement::Call { function, .. } => out.push(*function),
            Statement::Block(inner) => statement_calls(inner, out),
            Statement::If { accept, reject, .. } => {
                statement_calls(accept, out);
                statement_calls(reject, out);
            }
            Statement::Switch { cases, .. } => cases.iter().for_each(|case| statement_calls(&case.body, out)),
            Statement::Loop { body, continuing, .. } => {
                statement_calls(body, out);
                statement_calls(continuing, out);
            }
            _ => {}
        }
    }
}

/// Where each resource of a pass is bound.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct PassLayout {
    /// Each resource's `(group, binding)`, by name.
    pub slots: BTreeMap<String, (u32, u32)>,
}

/// Lays out a pass from the resources of all its modules (in variant order). Explicit bindings
/// are kept; the rest are numbered in order of first appearance within their group.
pub fn layout(modules: &[&[Declared]], names: &GroupNames) -> (PassLayout, Vec<(usize, usize, String)>) {
    let mut explicit: BTreeMap<String, (u32, u32)> = BTreeMap::new();
    let mut owner: BTreeMap<(u32, u32), String> = BTreeMap::new();
    let mut clashes = Vec::new();
    let mut order: Vec<String> = Vec::new();
    for (m, declared) in modules.iter().enumerate() {
        for (d, resource) in declared.iter().enumerate() {
            if !order.contains(&resource.name) {
                order.push(resource.name.clone());
            }
            let Some(slot) = resource.explicit else { continue };
            match explicit.get(&resource.name) {
                Some(&first) if first != slot => clashes.push((
                    m,
                    d,
                    format!(
                        "`{}` is bound at @group({}) @binding({}) here but at @group({}) @binding({}) in another variant",
                        resource.name, slot.0, slot.1, first.0, first.1
                    ),
                )),
                _ => {
                    explicit.insert(resource.name.clone(), slot);
                }
            }
            match owner.get(&slot) {
                Some(other) if *other != resource.name => clashes.push((
                    m,
                    d,
                    format!(
                        "`{}` and `{other}` are both bound at @group({}) @binding({})",
                        resource.name, slot.0, slot.1
                    ),
                )),
                _ => {
                    owner.insert(slot, resource.name.clone());
                }
            }
        }
    }
    let mut layout = PassLayout { slots: explicit };
    for name in order {
        if layout.slots.contains_key(&name) {
            continue;
        }
        let group = group_for(&name, names);
        let binding = (0..).find(|b| !owner.contains_key(&(group, *b))).unwrap_or(0);
        owner.insert((group, binding), name.clone());
        layout.slots.insert(name, (group, binding));
    }
    (layout, clashes)
}

/// Gives every resource of the module its slot in the pass layout.
pub fn apply(module: &mut Module, layout: &PassLayout) {
    for (_, global) in module.global_variables.iter_mut() {
        if !is_resource(global.space) {
            continue;
        }
        if let Some(&(group, binding)) = global.name.as_ref().and_then(|n| layout.slots.get(n)) {
            global.binding = Some(ResourceBinding { group, binding });
        }
    }
}
