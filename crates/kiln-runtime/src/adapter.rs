//! Which adapter a renderer, the tests and `kiln accuracy` run on.

/// Why there is no adapter to run on.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum AdapterError {
    /// wgpu found no adapter at all.
    #[error("no GPU adapter (no Vulkan, Metal or DirectX 12 driver, nor OpenGL)")]
    NoAdapter,
    /// Every adapter found is below WebGPU: each named, with what it lacks.
    #[error("no adapter runs WebGPU in full: {}", .0.join("; "))]
    BelowWebGpu(Vec<String>),
}

/// The first adapter of wgpu's OpenGL back end (Mesa's llvmpipe through EGL in CI), which
/// [`adapter`] passes by as below WebGPU: for the tests that hold kiln's output to GL too.
pub fn gl_adapter() -> Result<wgpu::Adapter, AdapterError> {
    let instance = wgpu::Instance::new(wgpu::InstanceDescriptor {
        backends: wgpu::Backends::GL,
        ..wgpu::InstanceDescriptor::new_without_display_handle_from_env()
    });
    let adapters = pollster::block_on(instance.enumerate_adapters(wgpu::Backends::GL));
    adapters.into_iter().next().ok_or(AdapterError::NoAdapter)
}

/// The adapter that runs WebGPU in full, a discrete GPU first and a CPU rasteriser last. An
/// adapter below WebGPU (wgpu's OpenGL backend on Mesa lacks depth copies, and lays out blocks
/// with `@size`/`@align` members wrongly: docs/backends.md) is named in the error instead of
/// being used: its results would not be WebGPU's.
pub fn adapter(backends: wgpu::Backends) -> Result<wgpu::Adapter, AdapterError> {
    let adapters = |backends: wgpu::Backends| {
        let instance = wgpu::Instance::new(wgpu::InstanceDescriptor {
            backends,
            ..wgpu::InstanceDescriptor::new_without_display_handle_from_env()
        });
        pollster::block_on(instance.enumerate_adapters(backends))
    };
    // Vulkan, Metal and DirectX 12 first: only where none runs WebGPU is OpenGL asked (its EGL
    // probe prints to stderr), to name what it lacks.
    let primary = adapters(backends & wgpu::Backends::PRIMARY);
    let rest = match primary.iter().any(|a| a.get_downlevel_capabilities().is_webgpu_compliant()) {
        true => Vec::new(),
        false => adapters(backends - wgpu::Backends::PRIMARY),
    };
    let adapters = primary.into_iter().chain(rest);
    let rank = |adapter: &wgpu::Adapter| match adapter.get_info().device_type {
        wgpu::DeviceType::DiscreteGpu => 0,
        wgpu::DeviceType::IntegratedGpu => 1,
        wgpu::DeviceType::VirtualGpu => 2,
        wgpu::DeviceType::Other => 3,
        wgpu::DeviceType::Cpu => 4,
    };
    let (full, below): (Vec<_>, Vec<_>) =
        adapters.partition(|a| a.get_downlevel_capabilities().is_webgpu_compliant());
    if let Some(best) = full.into_iter().min_by_key(rank) {
        return Ok(best);
    }
    if below.is_empty() {
        return Err(AdapterError::NoAdapter);
    }
    let named: Vec<String> = below
        .iter()
        .map(|adapter| {
            let info = adapter.get_info();
            let capabilities = adapter.get_downlevel_capabilities();
            let missing = wgpu::DownlevelFlags::compliant() - capabilities.flags;
            format!(
                "{} ({:?}) lacks {missing:?}, shader model {:?}",
                info.name, info.backend, capabilities.shader_model
            )
        })
        .collect();
    Err(AdapterError::BelowWebGpu(named))
}
