<!DOCTYPE PickedPoints>
<PickedPoints>
 <DocumentData>
  <DataFileName name="man.off"/>
  <templateName name=""/>
 </DocumentData>
 <point x="-0.0286574" y="-0.0257813" z="0.5" active="1" name="head_top"/>
 <point x="-0.0299138" y="-0.0874233" z="0.401963" active="1" name="nose_tip"/>
 <point x="-0.0263489" y="-0.0661836" z="0.36195" active="1" name="chin"/>
 <point x="0.0245658" y="-0.00880338" z="0.436881" active="1" name="left_ear"/>
 <point x="-0.0787105" y="-0.00358601" z="0.435913" active="1" name="right_ear"/>
 <point x="0.055904" y="-0.0150893" z="0.344159" active="1" name="left_shoulder"/>
 <point x="-0.109793" y="0.0327736" z="0.3406" active="1" name="right_shoulder"/>
 <point x="0.131333" y="-0.0482556" z="0.147938" active="1" name="left_elbow"/>
 <point x="-0.166407" y="0.0674699" z="0.144669" active="1" name="right_elbow"/>
 <point x="0.12301" y="-0.0951793" z="0.031294" active="1" name="left_wrist"/>
 <point x="-0.187592" y="0.0421848" z="0.0196805" active="1" name="right_wrist"/>
 <point x="0.119245" y="-0.097221" z="-0.0147762" active="1" name="left_hand_tip"/>
 <point x="-0.192665" y="0.0283689" z="-0.0827722" active="1" name="right_hand_tip"/>
 <point x="-0.0429674" y="-0.0716718" z="0.256119" active="1" name="chest"/>
 <point x="-0.0496875" y="-0.0720108" z="0.111532" active="1" name="navel"/>
 <point x="-0.0112167" y="0.0604653" z="0.25754" active="1" name="upper_back"/>
 <point x="-0.028863" y="0.00140541" z="-0.0314546" active="1" name="crotch"/>
 <point x="0.0593437" y="-0.0604612" z="0.0369456" active="1" name="left_hip"/>
 <point x="-0.104115" y="0.0177667" z="0.0372383" active="1" name="right_hip"/>
 <point x="0.103846" y="-0.0784192" z="-0.220754" active="1" name="left_knee"/>
 <point x="-0.133956" y="0.0344492" z="-0.229335" active="1" name="right_knee"/>
 <point x="0.188439" y="-0.026666" z="-0.488765" active="1" name="left_heel"/>
 <point x="-0.137832" y="0.13855" z="-0.495284" active="1" name="right_heel"/>
 <point x="0.164698" y="-0.145867" z="-0.476184" active="1" name="left_toe"/>
 <point x="-0.203663" y="0.0364107" z="-0.495963" active="1" name="right_toe"/>
 <point x="-0.0309878" y="-0.0789487" z="0.461935" active="1" name="head_top~nose_tip@50"/>
 <point x="0.00967453" y="-0.0524249" z="0.415085" active="1" name="left_ear~nose_tip@50"/>
 <point x="-0.0678864" y="-0.0485074" z="0.414359" active="1" name="right_ear~nose_tip@50"/>
 <point x="-0.0322006" y="-0.0318004" z="0.323977" active="1" name="chin~chest@50"/>
 <point x="-0.0246025" y="0.0280504" z="0.392194" active="1" name="head_top~upper_back@50"/>
 <point x="0.00713867" y="0.00337366" z="0.375318" active="1" name="left_ear~left_shoulder@50"/>
 <point x="-0.0568623" y="0.016219" z="0.375724" active="1" name="right_ear~right_shoulder@50"/>
 <point x="0.0838856" y="-0.00068535" z="0.289677" active="1" name="left_shoulder~left_elbow@33"/>
 <point x="0.104335" y="-0.02422" z="0.218327" active="1" name="left_shoulder~left_elbow@67"/>
 <point x="-0.121766" y="0.0547212" z="0.285166" active="1" name="right_shoulder~right_elbow@33"/>
 <point x="-0.139911" y="0.061983" z="0.218991" active="1" name="right_shoulder~right_elbow@67"/>
 <point x="0.134312" y="-0.0700983" z="0.0796047" active="1" name="left_elbow~left_wrist@50"/>
 <point x="-0.18417" y="0.0611881" z="0.0754151" active="1" name="right_elbow~right_wrist@50"/>
 <point x="0.11737" y="-0.100658" z="-0.0154799" active="1" name="left_wrist~left_hand_tip@50"/>
 <point x="-0.180071" y="0.0371484" z="-0.0335876" active="1" name="right_wrist~right_hand_tip@50"/>
 <point x="0.00300615" y="-0.0432424" z="0.318299" active="1" name="chest~left_shoulder@50"/>
 <point x="-0.0580887" y="-0.0241778" z="0.326357" active="1" name="chest~right_shoulder@50"/>
 <point x="0.0555923" y="0.0408576" z="0.3019" active="1" name="upper_back~left_shoulder@50"/>
 <point x="-0.0648564" y="0.0767313" z="0.295538" active="1" name="upper_back~right_shoulder@50"/>
 <point x="-0.0481549" y="-0.0799137" z="0.183875" active="1" name="chest~navel@50"/>
 <point x="-0.0601795" y="-0.0584521" z="0.0189713" active="1" name="navel~crotch@50"/>
 <point x="-0.0215548" y="0.0233843" z="0.14755" active="1" name="upper_back~crotch@33"/>
 <point x="0.00123799" y="0.0328812" z="0.0512937" active="1" name="upper_back~crotch@67"/>
 <point x="0.0306039" y="-0.069709" z="0.159209" active="1" name="chest~left_hip@50"/>
 <point x="-0.0958163" y="-0.0408563" z="0.137625" active="1" name="chest~right_hip@50"/>
 <point x="0.0331956" y="-0.00023208" z="0.14298" active="1" name="upper_back~left_hip@50"/>
 <point x="-0.0554385" y="0.035108" z="0.143814" active="1" name="upper_back~right_hip@50"/>
 <point x="0.0496957" y="-0.0546844" z="0.206477" active="1" name="left_shoulder~left_hip@50"/>
 <point x="-0.106628" y="0.0383762" z="0.199864" active="1" name="right_shoulder~right_hip@50"/>
 <point x="0.0894283" y="-0.066822" z="-0.0559394" active="1" name="left_hip~left_knee@33"/>
 <point x="0.111682" y="-0.0642807" z="-0.136216" active="1" name="left_hip~left_knee@67"/>
 <point x="-0.126753" y="0.028573" z="-0.0474498" active="1" name="right_hip~right_knee@33"/>
 <point x="-0.140114" y="0.037158" z="-0.147742" active="1" name="right_hip~right_knee@67"/>
 <point x="0.0267668" y="-0.0734767" z="-0.0910427" active="1" name="crotch~left_knee@50"/>
 <point x="-0.068145" y="0.00303201" z="-0.131028" active="1" name="crotch~right_knee@50"/>
 <point x="0.157543" y="-0.0630216" z="-0.380278" active="1" name="left_knee~left_toe@50"/>
 <point x="-0.146139" y="0.084509" z="-0.390385" active="1" name="right_knee~right_toe@50"/>
 <point x="0.187332" y="-0.0931443" z="-0.48313" active="1" name="left_heel~left_toe@50"/>
 <point x="-0.171866" y="0.0894896" z="-0.4966" active="1" name="right_heel~right_toe@50"/>
 <point x="0.130431" y="-0.0600216" z="-0.228324" active="1" name="left_hip~left_heel@50"/>
 <point x="-0.140972" y="0.0700915" z="-0.235993" active="1" name="right_hip~right_heel@50"/>
 <point x="0.178087" y="-0.0519798" z="-0.395431" active="1" name="left_hip~left_heel@80"/>
 <point x="-0.140955" y="0.120858" z="-0.397946" active="1" name="right_hip~right_heel@80"/>
 <point x="0.0562538" y="0.00275161" z="0.0445804" active="1" name="upper_back~crotch@67~left_hip@50"/>
 <point x="-0.0565655" y="0.0550601" z="0.0454489" active="1" name="upper_back~crotch@67~right_hip@50"/>
</PickedPoints>
