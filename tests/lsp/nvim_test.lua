-- Neovim's built-in LSP client against `f2 lsp`: open a scene with errors and
-- check that every diagnostic arrives at the right line and byte column
-- (Neovim converts the server's UTF-16 columns back to bytes).
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

vim.lsp.stop_client(client)
if #failures > 0 then
  io.stderr:write(table.concat(failures, "\n") .. "\nFAILED\n")
  vim.cmd("cquit 1")
else
  io.stdout:write("ok: Neovim received every diagnostic at its place\n")
  vim.cmd("qall!")
end
