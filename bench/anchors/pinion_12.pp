<!DOCTYPE PickedPoints>
<PickedPoints>
 <DocumentData>
  <DataFileName name="pinion.off"/>
  <templateName name=""/>
 </DocumentData>
 <point x="-0.218255" y="-0.344188" z="0.454309" active="1" name="bottom_inner_000"/>
 <point x="-0.512876" y="-0.325787" z="-0.057727" active="1" name="bottom_inner_120"/>
 <point x="-0.481444" y="0.1711" z="0.33382" active="1" name="bottom_inner_240"/>
 <point x="-0.332057" y="-0.834246" z="-0.079254" active="1" name="bottom_outer_072"/>
 <point x="-0.831738" y="0.261486" z="-0.228702" active="1" name="bottom_outer_180"/>
 <point x="-0.237446" y="0.261529" z="0.829243" active="1" name="bottom_outer_288"/>
 <point x="0.504051" y="-0.175129" z="-0.296298" active="1" name="top_inner_060"/>
 <point x="0.221988" y="0.377082" z="-0.425447" active="1" name="top_inner_180"/>
 <point x="0.533331" y="0.288581" z="0.069012" active="1" name="top_inner_300"/>
 <point x="0.831738" y="-0.261486" z="0.228702" active="1" name="top_outer_000"/>
 <point x="0.237446" y="-0.261529" z="-0.829243" active="1" name="top_outer_108"/>
 <point x="0.10502" y="0.834199" z="-0.324933" active="1" name="top_outer_216"/>
</PickedPoints>
