-- Neovim's built-in LSP client against `f2 lsp`: open a scene with errors and
-- check that every diagnostic arrives at the right line and byte column
-- (Neovim converts the server's UTF-16 columns back to bytes); then follow a
-- variable into an included file and rename it across both files.
--   F2=path/to/f2 SCENE=path/to/broken.f2 nvim --headless --clean -c "luafile nvim_test.lua"
-- Exit code 0 when all checks pass.
local f2, scene = os.getenv("F2"), os.getenv("SCENE")
local failures = {}
local function check(what, got, want)
  if got ~= want then
    table.insert(failures, string.format("%s: got %s, want %s", what, vim.inspect(got), vim.inspect(want)))
  end
end

vim.cmd("edit " .. vim.fn.fnameescape(scene))
local buf = vim.api.nvim_get_current_buf()
-- vim.lsp.start_client + buf_attach_client work from Neovim 0.7 on (vim.lsp.start is 0.8+).
local client = vim.lsp.start_client({ name = "f2", cmd = { f2, "lsp" }, root_dir = vim.fn.fnamemodify(scene, ":h") })
vim.lsp.buf_attach_client(buf, client)

-- A bounded wait for the event itself (the diagnostics), not a fixed sleep.
local arrived = vim.wait(60000, function() return #vim.diagnostic.get(buf) >= 3 end, 10)
check("diagnostics arrived", arrived, true)

local got = vim.diagnostic.get(buf)
table.sort(got, function(a, b) return a.lnum < b.lnum or (a.lnum == b.lnum and a.col < b.col) end)
local want = {
  { lnum = 3, col = 10, end_col = 14, message = "expected a number, got '\u{1F600}' (it contains U+1F600 at column 11, but commands, names and numbers are plain ASCII)" },
  { lnum = 3, col = 15, end_col = 18, message = "green must be a whole number from 0 to 255, got 300" },
  { lnum = 4, col = 10, end_col = 14, message = "unknown part 'lhnd' (did you mean 'lhand'?)" },
}
check("number of diagnostics", #got, #want)
for i, w in ipairs(want) do
  local g = got[i] or {}
  for _, key in ipairs({ "lnum", "col", "end_col", "message" }) do
    check(string.format("diagnostic %d %s", i, key), g[key], w[key])
  end
  check(string.format("diagnostic %d severity", i), g.severity, vim.diagnostic.severity.ERROR)
end

-- A scene with an include (data/included): go to definition from main.f2 into
-- parts/stage.f2, then rename there and back; Neovim applies the WorkspaceEdit
-- to both files (in buffers; nothing is written to disk).
local included = os.getenv("INCLUDED")
vim.cmd("edit " .. vim.fn.fnameescape(included .. "/main.f2"))
local main = vim.api.nvim_get_current_buf()
vim.lsp.buf_attach_client(main, client)
local at = { textDocument = { uri = vim.uri_from_bufnr(main) }, position = { line = 2, character = 20 } }
local function only(responses)
  for _, r in pairs(responses or {}) do return r.result end
end
local definition = only(vim.lsp.buf_request_sync(main, "textDocument/definition", at, 60000)) or {}
check("definition of h: file", definition.uri, vim.uri_from_fname(included .. "/parts/stage.f2"))
check("definition of h: line", definition.range and definition.range.start.line, 1)
at.newName = "height"
local edit = only(vim.lsp.buf_request_sync(main, "textDocument/rename", at, 60000))
check("rename of h answered", edit ~= nil, true)
if edit then vim.lsp.util.apply_workspace_edit(edit, "utf-16") end
local stage = vim.fn.bufnr(included .. "/parts/stage.f2")
check("stage.f2 renamed", stage >= 0 and vim.api.nvim_buf_get_lines(stage, 1, 2, false)[1], "/let height 25")
check("main.f2 renamed", vim.api.nvim_buf_get_lines(main, 4, 5, false)[1], "/key 10 prop 0 (height * 2) 0 0 0 0")

vim.lsp.stop_client(client)
if #failures > 0 then
  io.stderr:write(table.concat(failures, "\n") .. "\nFAILED\n")
  vim.cmd("cquit 1")
else
  io.stdout:write("ok: Neovim received every diagnostic at its place and renamed across an include\n")
  vim.cmd("qall!")
end
