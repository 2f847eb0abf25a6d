/* plugin_elf.c - reads a module's ELF headers and dynamic symbol table from the file, so that a file that is not
 * a module is refused before dlopen would run its constructors. Every offset and size read from the file is
 * checked against the file's length before it is used. */
#include "plugin_elf.h"
#include "generic/plugin.h"

#include <elf.h>
#include <link.h>
#include <stdint.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>

#if defined(__x86_64__)
#define NATIVE_MACHINE EM_X86_64
#elif defined(__aarch64__)
#define NATIVE_MACHINE EM_AARCH64
#elif defined(__i386__)
#define NATIVE_MACHINE EM_386
#elif defined(__arm__)
#define NATIVE_MACHINE EM_ARM
#elif defined(__riscv)
#define NATIVE_MACHINE EM_RISCV
#elif defined(__powerpc64__)
#define NATIVE_MACHINE EM_PPC64
#else
#define NATIVE_MACHINE EM_NONE /* not checked */
#endif

#if __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
#define NATIVE_DATA ELFDATA2LSB
#else
#define NATIVE_DATA ELFDATA2MSB
#endif

#if __SIZEOF_POINTER__ == 8
#define NATIVE_CLASS ELFCLASS64
#else
#define NATIVE_CLASS ELFCLASS32
#endif

/* 1 when [off, off + size) lies inside a file of len bytes. */
static int inside(uint64_t off, uint64_t size, size_t len) { return off <= len && size <= len - off; }

static int refuse(GError *err, const char *path, const char *why)
{
    return gerror_set(err, G_ERR_IO, "cannot load module '%s': %s (not loaded, nothing of it was run)", path, why);
}

/* Looks for the two module symbols in the dynamic symbol table; the file is mapped at base, len bytes. */
static int check_symbols(const unsigned char *base, size_t len, const char *path, int *abi, GError *err)
{
    const ElfW(Ehdr) *eh = (const ElfW(Ehdr) *)base;
    if (eh->e_shentsize != sizeof(ElfW(Shdr)) || eh->e_shnum == 0 ||
        !inside(eh->e_shoff, (uint64_t)eh->e_shnum * sizeof(ElfW(Shdr)), len) || eh->e_shoff % sizeof(void *))
        return refuse(err, path, "it has no readable section table");
    const ElfW(Shdr) *sh = (const ElfW(Shdr) *)(base + eh->e_shoff);
    const ElfW(Shdr) *dynsym = NULL;
    for (int i = 0; i < eh->e_shnum && !dynsym; i++)
        if (sh[i].sh_type == SHT_DYNSYM)
            dynsym = &sh[i];
    if (!dynsym || dynsym->sh_entsize != sizeof(ElfW(Sym)) || !inside(dynsym->sh_offset, dynsym->sh_size, len) ||
        dynsym->sh_offset % sizeof(void *) || dynsym->sh_link >= eh->e_shnum)
        return refuse(err, path, "it has no dynamic symbol table");
    const ElfW(Shdr) *strtab = &sh[dynsym->sh_link];
    if (strtab->sh_type != SHT_STRTAB || !inside(strtab->sh_offset, strtab->sh_size, len) || strtab->sh_size == 0)
        return refuse(err, path, "its dynamic symbol table has no string table");
    const char *names = (const char *)base + strtab->sh_offset;
    const ElfW(Sym) *syms = (const ElfW(Sym) *)(base + dynsym->sh_offset);
    size_t nsyms = dynsym->sh_size / sizeof(ElfW(Sym));
    const ElfW(Sym) *abi_sym = NULL, *init_sym = NULL;
    for (size_t i = 0; i < nsyms; i++) {
        const ElfW(Sym) *s = &syms[i];
        if (s->st_name >= strtab->sh_size || s->st_shndx == SHN_UNDEF)
            continue;
        int bind = ELF64_ST_BIND(s->st_info), type = ELF64_ST_TYPE(s->st_info);
        if (bind != STB_GLOBAL && bind != STB_WEAK)
            continue;
        const char *name = names + s->st_name;
        size_t room = strtab->sh_size - s->st_name;
        if (strnlen(name, room) == room)
            continue; /* not terminated inside the table */
        if (strcmp(name, GMODULE_ABI_SYMBOL) == 0 && type == STT_OBJECT)
            abi_sym = s;
        else if (strcmp(name, GMODULE_INIT_SYMBOL) == 0 && type == STT_FUNC)
            init_sym = s;
    }
    if (!abi_sym && !init_sym)
        return refuse(err, path, "it is a shared object but not a libgeneric module (it defines neither "
                                 GMODULE_ABI_SYMBOL " nor " GMODULE_INIT_SYMBOL ")");
    if (!abi_sym)
        return refuse(err, path, "it defines no " GMODULE_ABI_SYMBOL " (an int)");
    if (!init_sym)
        return refuse(err, path, "it has no entry point: it defines no function " GMODULE_INIT_SYMBOL);
    /* the version's value, from the section that holds it */
    *abi = -1;
    if (abi_sym->st_size == sizeof(int) && abi_sym->st_shndx < eh->e_shnum) {
        const ElfW(Shdr) *sec = &sh[abi_sym->st_shndx];
        uint64_t at = abi_sym->st_value - sec->sh_addr;
        if (sec->sh_type != SHT_NOBITS && abi_sym->st_value >= sec->sh_addr && inside(at, sizeof(int), sec->sh_size) &&
            inside(sec->sh_offset + at, sizeof(int), len))
            memcpy(abi, base + sec->sh_offset + at, sizeof(int));
    }
    return G_OK;
}

int gplugin_elf_check(int fd, const char *path, int *abi, GError *err)
{
    *abi = -1;
    struct stat st;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode))
        return refuse(err, path, "it is not a regular file");
    if ((uint64_t)st.st_size < sizeof(ElfW(Ehdr)))
        return refuse(err, path, "it is too short to be a shared object");
    size_t len = (size_t)st.st_size;
    unsigned char *base = mmap(NULL, len, PROT_READ, MAP_PRIVATE, fd, 0);
    if (base == MAP_FAILED)
        return refuse(err, path, "it cannot be mapped for reading");
    const ElfW(Ehdr) *eh = (const ElfW(Ehdr) *)base;
    int rc = G_OK;
    if (memcmp(eh->e_ident, ELFMAG, SELFMAG) != 0)
        rc = refuse(err, path, "it is not an ELF file (invalid ELF header)");
    else if (eh->e_ident[EI_CLASS] != NATIVE_CLASS || eh->e_ident[EI_DATA] != NATIVE_DATA)
        rc = refuse(err, path, "it is an ELF file for another word size or byte order");
    else if (NATIVE_MACHINE != EM_NONE && eh->e_machine != NATIVE_MACHINE)
        rc = refuse(err, path, "it is an ELF file for another processor");
    else if (eh->e_type != ET_DYN)
        rc = refuse(err, path, "it is an ELF file but not a shared object");
    else
        rc = check_symbols(base, len, path, abi, err);
    munmap(base, len);
    return rc;
}
