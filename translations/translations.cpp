// SPDX-License-Identifier: GPL-3.0-or-later
// Anchor of the fivebar_translations library, whose content is the embedded .qm resources.
namespace fivebar::translations {
// The resource directory the studio loads translations from.
const char* resourcePrefix() { return ":/i18n"; }
}  // namespace fivebar::translations
