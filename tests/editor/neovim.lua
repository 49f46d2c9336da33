-- Drives `kiln lsp` from Neovim's built-in LSP client (Neovim 0.7 or later, headless), as an
-- editor user would: the set-up docs/editor.md gives, then open a file of a project, type an
-- error into it, read the diagnostics the editor shows. Run by tests/it/lsp.rs:
--   KILN=.../kiln KILN_FILE=.../LitPass.wgsl KILN_CACHE=... KILN_OUT=... \
--     nvim --headless --clean -c "luafile tests/editor/neovim.lua"
local kiln, file = os.getenv("KILN"), os.getenv("KILN_FILE")
local out = io.open(os.getenv("KILN_OUT"), "w")

local function finish(status)
  out:write("status ", status, "\n")
  out:close()
  vim.cmd("qa!")
end

-- docs/editor.md's set-up for Neovim 0.7 to 0.10, with the binary and cache under test.
local kiln_client
vim.api.nvim_create_autocmd({ "BufReadPost", "BufNewFile" }, {
  pattern = { "*.shader", "*.compute", "*.wgsl", "*.mat", "kiln.toml" },
  callback = function(args)
    kiln_client = kiln_client or vim.lsp.start_client({
      name = "kiln",
      cmd = { kiln, "lsp", "--cache-dir", os.getenv("KILN_CACHE") },
      root_dir = vim.fn.getcwd(),
    })
    vim.lsp.buf_attach_client(args.buf, kiln_client)
  end,
})

vim.cmd("edit " .. vim.fn.fnameescape(file))
local buf = vim.api.nvim_get_current_buf()
local ready = vim.wait(30000, function()
  local client = kiln_client and vim.lsp.get_client_by_id(kiln_client)
  return client ~= nil and client.initialized
end, 20)
if not ready then return finish("not-initialized") end

-- Type a line that uses a name nothing declares, after the `discard;` of the clipping branch.
local after
for i, line in ipairs(vim.api.nvim_buf_get_lines(buf, 0, -1, false)) do
  if line:find("discard;", 1, true) then after = i end
end
vim.api.nvim_buf_set_lines(buf, after, after, false, { "        let oops: f32 = undefined_thing;" })
out:write("typed-at ", after, "\n")

local shown = vim.wait(30000, function()
  return #vim.diagnostic.get(buf, { severity = vim.diagnostic.severity.ERROR }) > 0
end, 20)
for _, d in ipairs(vim.diagnostic.get(buf, { severity = vim.diagnostic.severity.ERROR })) do
  out:write(string.format("error %d %d %s\n", d.lnum, d.col, (d.message:gsub("\n", " | "))))
end
finish(shown and "ok" or "no-diagnostics")
