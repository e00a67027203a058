// Linked into every executable of the sanitizer build (COSIM_SANITIZE). Open MPI unloads its
// plugins in MPI_Finalize, before LeakSanitizer looks at exit: the leaks made inside them then
// come from an "<unknown module>" that no suppression can name, and the memory they still
// point to counts as leaked. Defined in the executable, this dlclose comes before the C
// library's for every library, so nothing is ever unloaded.
int dlclose(void* handle) {
  (void)handle;
  return 0;
}
