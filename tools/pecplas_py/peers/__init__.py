"""The same problems for other codes: CalculiX input from our decks (export_abaqus), the OpenSees
elastic block (opensees_block)."""
